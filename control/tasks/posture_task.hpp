// Posture task (paper II-D): qddot = -Kp (q - q_ref) - Kd qdot; a moving
// reference (a timed joint-space move) adds its velocity and acceleration:
// qddot = qddot_ref - Kp (q - q_ref) - Kd (qdot - qdot_ref).
// Rows: 7, over the qddot block. Defaults stiffness 10, damping 2 sqrt(10)
// (weight 5 is set in the Formulation by the controller). Real-time safe.
#pragma once

#include <string>

#include "control/formulation/task.hpp"
#include "control/tasks/pd_gains.hpp"

namespace handover::control {

class PostureTask : public Task {
 public:
  explicit PostureTask(std::string name = "posture", PdGains gains = PdGains::critical(10.0),
                       const Vector7& q_ref = Vector7::Zero());

  const std::string& name() const override { return name_; }
  int rows() const override { return kArmDofs; }
  void compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::VectorXd> b) override;

  /// Reference posture, rad.
  void setTarget(const Vector7& q_ref) {
    q_ref_ = q_ref;
    qd_ref_.setZero();
    qdd_ref_.setZero();
  }
  /// Generic handles: joint target (kConfigured = the constructor's q_ref),
  /// gains (`translation` is the joint gain; configured = the constructor's).
  bool applyTarget(const TaskTarget& target) override;
  bool applyGains(const TaskGains& gains) override;
  const Vector7& target() const { return q_ref_; }
  void setGains(const PdGains& gains) { gains_ = gains; }
  const PdGains& gains() const { return gains_; }

 private:
  std::string name_;
  PdGains gains_;
  Vector7 q_ref_;
  Vector7 qd_ref_ = Vector7::Zero(), qdd_ref_ = Vector7::Zero();  ///< rad/s, rad/s^2 of a moving reference
  PdGains configured_gains_;
  Vector7 configured_q_ref_;
};

}  // namespace handover::control
