#include "control/constraints/joint_position_limit.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "control/constraints/bound_tightening.hpp"

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

namespace {

// Lowest admissible velocity away-from-limit coordinate for one side, where
// the joint coordinate x grows away from the limit (d = x - limit) and x_dot
// is its velocity. Returns the lower bound on x_ddot (or -inf when free).
double sideBound(double d, double x_dot, double di, double ds, double offset, double recovery, double dt,
                 double& xi) {
  if (d >= di) {
    xi = 0.0;
    return -std::numeric_limits<double>::infinity();
  }
  const double span = di - ds;
  if (xi <= 0.0) {
    // entering: start the bound at the current approach speed, plus slack
    const double approach = std::max(0.0, -x_dot);
    const double gap = std::max(d - ds, 1e-9);
    xi = approach * span / gap + offset * span;
    xi = std::max(xi, 1e-9);
  }
  double v_min = -xi * (d - ds) / span;   // > 0 inside the safety zone: move out
  v_min = std::min(v_min, recovery);
  const double damper = (v_min - x_dot) / dt;
  // never predict beyond ds/2 from the limit over the next step
  const double position = 2.0 * (0.5 * ds - d - x_dot * dt) / (dt * dt);
  return std::max(damper, position);
}

}  // namespace

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
    const double lo = sideBound(q[i] - q_min_[i], qd[i], di, ds, off, rec, ctx.dt, xi_lower_[i]);
    // upper limit: x = -q
    const double hi = -sideBound(q_max_[i] - q[i], -qd[i], di, ds, off, rec, ctx.dt, xi_upper_[i]);
    tightenBounds(chi_lb, chi_ub, VariableLayout::kQdd + i, lo, hi);
  }
  return 0;
}

}  // namespace handover::control
