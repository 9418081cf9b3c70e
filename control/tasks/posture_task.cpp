#include "control/tasks/posture_task.hpp"

namespace handover::control {

PostureTask::PostureTask(std::string name, PdGains gains, const Vector7& q_ref)
    : name_(std::move(name)), gains_(gains), q_ref_(q_ref), configured_gains_(gains), configured_q_ref_(q_ref) {}

bool PostureTask::applyTarget(const TaskTarget& target) {
  if (target.kind == TaskTarget::Kind::kPose) return false;
  const bool joints = target.kind == TaskTarget::Kind::kJoints;
  q_ref_ = joints ? target.q : configured_q_ref_;
  qd_ref_ = joints ? target.qd : Vector7::Zero();
  qdd_ref_ = joints ? target.qdd : Vector7::Zero();
  return true;
}

bool PostureTask::applyGains(const TaskGains& gains) {
  gains_ = gains.configured ? configured_gains_ : gains.translation;
  return true;
}

void PostureTask::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::VectorXd> b) {
  const Data& data = *ctx.data;
  A.block<kArmDofs, kArmDofs>(0, VariableLayout::kQdd).setIdentity();
  b.head<kArmDofs>() = qdd_ref_ - gains_.stiffness * (data.q - q_ref_) - gains_.damping * (data.v - qd_ref_);
}

}  // namespace handover::control
