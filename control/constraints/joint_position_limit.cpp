#include "control/constraints/joint_position_limit.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "control/constraints/bound_tightening.hpp"
#include "control/constraints/velocity_damper.hpp"

namespace handover::control {

JointPositionLimit::JointPositionLimit(const Model& model, const JointPositionLimitParams& params, std::string name)
    : name_(std::move(name)), params_(params), q_min_(model.q_min), q_max_(model.q_max) {
  if (!(params.safety >= 0.0 && params.safety < params.interaction && params.interaction <= 0.5))
    throw std::invalid_argument("JointPositionLimit '" + name_ + "': need 0 <= safety < interaction <= 0.5");
  if (!(params.damper_offset >= 0.0) || !(params.recovery_speed >= 0.0))
    throw std::invalid_argument("JointPositionLimit '" + name_ + "': negative damper_offset or recovery_speed");
  reset();
}

void JointPositionLimit::reset() {
  xi_lower_.fill(0.0);
  xi_upper_.fill(0.0);
}

int JointPositionLimit::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd>, Eigen::Ref<Eigen::VectorXd>,
                                Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> chi_lb,
                                Eigen::Ref<Eigen::VectorXd> chi_ub) {
  const Vector7& q = ctx.data->q;
  const Vector7& qd = ctx.data->v;
  for (int i = 0; i < kArmDofs; ++i) {
    const double range = q_max_[i] - q_min_[i];
    const double di = params_.interaction * range;
    const double ds = params_.safety * range;
    const double off = params_.damper_offset;
    const double rec = params_.recovery_speed;
    // lower limit: x = q
    const double lo = velocityDamperBound(q[i] - q_min_[i], qd[i], di, ds, off, rec, ctx.dt, xi_lower_[i]);
    // upper limit: x = -q
    const double hi = -velocityDamperBound(q_max_[i] - q[i], -qd[i], di, ds, off, rec, ctx.dt, xi_upper_[i]);
    tightenBounds(chi_lb, chi_ub, VariableLayout::kQdd + i, lo, hi);
  }
  return 0;
}

}  // namespace handover::control
