#include "control/constraints/joint_velocity_limit.hpp"

#include "control/constraints/bound_tightening.hpp"

namespace handover::control {

JointVelocityLimit::JointVelocityLimit(const Model& model, double scale, std::string name)
    : name_(std::move(name)), v_max_(model.v_max), scale_(scale) {}

int JointVelocityLimit::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd>, Eigen::Ref<Eigen::VectorXd>,
                                Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> chi_lb,
                                Eigen::Ref<Eigen::VectorXd> chi_ub) {
  const Vector7& qd = ctx.data->v;
  const double s = scale_ * speed_scale_;
  for (int i = 0; i < kArmDofs; ++i) {
    const double v = s * v_max_[i];
    tightenBounds(chi_lb, chi_ub, VariableLayout::kQdd + i, (-v - qd[i]) / ctx.dt, (v - qd[i]) / ctx.dt);
  }
  return 0;
}

}  // namespace handover::control
