// Set-point pose task for a model frame (default "tcp"): used to retract or
// stow, and as the comparison baseline (a fixed handover location, no
// observation). Rows: 6 over qddot, world axes [translation; rotation]:
//
//   J qddot = -K e - D (J qdot - v*) - Jdot qdot,   e = [P - P*; q (-) q*]
//
// v*: the set-point's own velocity (zero for a fixed one): a set-point that
// moves (fingers riding along with an object being pulled out of them) is
// followed without the D v* / K lag a fixed-point PD leaves.
//
// Defaults: stiffness 2, damping 2 sqrt(2) for both parts. Real-time safe.
#pragma once

#include <string>

#include "control/formulation/task.hpp"
#include "control/tasks/pd_gains.hpp"

namespace handover::control {

class EndEffectorPoseTask : public Task {
 public:
  /// Throws std::out_of_range naming the frame if the model lacks it.
  EndEffectorPoseTask(const Model& model, std::string name = "pose", const std::string& frame = "tcp",
                      PdGains translation = PdGains::critical(2.0), PdGains orientation = PdGains::critical(2.0));

  const std::string& name() const override { return name_; }
  int rows() const override { return 6; }
  void compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::VectorXd> b) override;

  /// Target pose of the frame in the world.
  void setTarget(const Isometry& target) { target_ = target; }
  /// The target's velocity, [linear m/s; angular rad/s] world axes (zero: at rest).
  void setTargetVelocity(const Vector6& velocity) { target_velocity_ = velocity; }
  /// Generic handles: a pose target (world; kConfigured keeps the current
  /// one: a pose task has no configured target), gains (configured = the
  /// constructor's).
  bool applyTarget(const TaskTarget& target) override;
  bool applyGains(const TaskGains& gains) override;
  const Isometry& target() const { return target_; }
  void setGains(const PdGains& translation, const PdGains& orientation);
  const PdGains& translationGains() const { return translation_; }
  const PdGains& orientationGains() const { return orientation_; }
  /// e of the last compute() (m; rad).
  const Vector6& error() const { return error_; }

 private:
  std::string name_;
  int frame_id_ = 0;
  PdGains translation_, orientation_;
  PdGains configured_translation_, configured_orientation_;
  Isometry target_ = Isometry::Identity();
  Vector6 target_velocity_ = Vector6::Zero();
  Matrix6x7 J_ = Matrix6x7::Zero();
  Vector6 error_ = Vector6::Zero();
};

}  // namespace handover::control
