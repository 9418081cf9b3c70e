#include "control/constraints/joint_torque_limit.hpp"

namespace handover::control {

JointTorqueLimit::JointTorqueLimit(const Model& model, double scale, std::string name)
    : name_(std::move(name)), tau_max_(model.tau_max), scale_(scale) {}

int JointTorqueLimit::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
                              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd>,
                              Eigen::Ref<Eigen::VectorXd>) {
  const Data& data = *ctx.data;
  C.block<kArmDofs, kArmDofs>(0, VariableLayout::kQdd) = data.M;
  // tau = M qddot + h - tau_external within the limits
  lb.head<kArmDofs>() = -scale_ * tau_max_ - data.h + ctx.tau_external;
  ub.head<kArmDofs>() = scale_ * tau_max_ - data.h + ctx.tau_external;
  return kArmDofs;
}

}  // namespace handover::control
