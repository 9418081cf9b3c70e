#include "control/tasks/end_effector_pose_task.hpp"

#include "control/so3.hpp"

namespace handover::control {

EndEffectorPoseTask::EndEffectorPoseTask(const Model& model, std::string name, const std::string& frame,
                                         PdGains translation, PdGains orientation)
    : name_(std::move(name)), frame_id_(model.frameId(frame)), translation_(translation), orientation_(orientation),
      configured_translation_(translation), configured_orientation_(orientation) {}

bool EndEffectorPoseTask::applyTarget(const TaskTarget& target) {
  if (target.kind == TaskTarget::Kind::kJoints) return false;
  if (target.kind == TaskTarget::Kind::kPose) {
    target_ = target.pose;
    target_velocity_ = target.velocity;
  }
  return true;
}

bool EndEffectorPoseTask::applyGains(const TaskGains& gains) {
  if (gains.configured) setGains(configured_translation_, configured_orientation_);
  else setGains(gains.translation, gains.orientation);
  return true;
}

void EndEffectorPoseTask::setGains(const PdGains& translation, const PdGains& orientation) {
  translation_ = translation;
  orientation_ = orientation;
}

void EndEffectorPoseTask::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A,
                                  Eigen::Ref<Eigen::VectorXd> b) {
  const Model& model = *ctx.model;
  const Data& data = *ctx.data;
  const Isometry X = framePlacement(model, data, frame_id_);
  frameJacobian(model, data, frame_id_, J_);
  const Vector6 v = J_ * data.v - target_velocity_;
  const Vector6 drift = frameDrift(model, data, frame_id_);
  error_.head<3>() = X.translation() - target_.translation();
  error_.tail<3>() = orientationError(X.linear(), target_.linear());
  A.block<6, kArmDofs>(0, VariableLayout::kQdd) = J_;
  b.head<3>() = -translation_.stiffness * error_.head<3>() - translation_.damping * v.head<3>() - drift.head<3>();
  b.tail<3>() = -orientation_.stiffness * error_.tail<3>() - orientation_.damping * v.tail<3>() - drift.tail<3>();
}

}  // namespace handover::control
