#include "control/constraints/joint_velocity_limit.hpp"

#include <algorithm>
#include <cmath>

#include "control/constraints/bound_tightening.hpp"

namespace handover::control {

JointVelocityLimit::JointVelocityLimit(const Model& model, double scale, std::string name, double braking,
                                       double safety)
    : name_(std::move(name)),
      v_max_(model.v_max),
      a_max_(model.a_max),
      q_min_(model.q_min),
      q_max_(model.q_max),
      scale_(scale),
      braking_(braking),
      safety_(safety) {}

int JointVelocityLimit::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd>, Eigen::Ref<Eigen::VectorXd>,
                                Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> chi_lb,
                                Eigen::Ref<Eigen::VectorXd> chi_ub) {
  const Vector7& qd = ctx.data->v;
  const Vector7& q = ctx.data->q;
  const double s = scale_ * speed_scale_;
  for (int i = 0; i < kArmDofs; ++i) {
    const double v = s * v_max_[i];
    double up = v, down = v;
    if (braking_ > 0.0) {
      // the speed from which the joint still stops short of its limit's safety distance
      const double ds = safety_ * (q_max_[i] - q_min_[i]);
      const double a = 2.0 * braking_ * a_max_[i];
      up = std::min(up, std::sqrt(a * std::max(0.0, q_max_[i] - ds - q[i])));
      down = std::min(down, std::sqrt(a * std::max(0.0, q[i] - q_min_[i] - ds)));
    }
    tightenBounds(chi_lb, chi_ub, VariableLayout::kQdd + i, (-down - qd[i]) / ctx.dt, (up - qd[i]) / ctx.dt);
  }
  return 0;
}

}  // namespace handover::control
