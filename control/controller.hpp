// The task-space QP controller (paper section II), run every control period:
//
//   computeAll(q, qdot) -> tasks and constraints fill one QP over
//   chi = [qddot (7); alphadot_obs (6)] -> solve -> integrate the observed
//   object with alphadot_obs -> tau = M qddot + h - J_ft^T f (payload included;
//   f the known external wrench at the wrist sensor, setExternalWrench; while
//   carrying, the observed joint disturbance instead, setDisturbanceFeedback).
//
// The tasks and constraints are the entries of config/controller.yaml's
// `tasks:` and `constraints:` lists, built in order through a registry of
// types (controller_registry.hpp). Shipped: tasks "observation",
// "tracking", "posture", "pose" (disabled at start); constraints
// "joint_acceleration", "joint_position", "joint_velocity", "joint_torque"
// and "collision" (built when the caller hands over a collision scene). The
// controller needs one task of type observation and one of type
// trajectory_tracking (the observed object and the grasp frame); the others
// may be left out. Keep "observation" on whenever "tracking" is on: the tracking rows
// also involve alphadot_obs, and without the (much heavier) observation task
// only the regularisation would stop them from moving the observed object.
// Any task is addressed by its name through generic handles (taskIndex,
// then setTaskEnabled / setTaskTarget / setTaskGains / setTaskOffset), which
// is how the state machine reaches it (runtime/adapter). A speed scale below 1
// (setSpeedScale: the slow-down near a person) gives way first: when the rows
// cannot all hold under it, the QP is solved again at the full velocity
// limits (counted: unslowedCount), so a person moving in faster than the
// slowed arm may move is still escaped. When the rows cannot all hold and some are soft (collision),
// they are relaxed by the least common amount and the QP solved again
// (SoftRowRelaxation; counted: relaxedCount, lastSlack) - the arm keeps
// within its own limits and escapes as well as they allow. If the QP still
// fails (any status but optimal) or the inputs hold
// NaN/inf, the controller falls back to a damped stop
// qddot = -kd qdot clipped to the acceleration limits; fallbacks are counted
// with the QP status and the reason (fallbackStreak, lastFallbackReason), never
// printed here: the application logs them (the step does no I/O).
// Either way the command passes the limit guard last (safety/limit_guard.hpp,
// config limit_guard): from the measured state and the model alone, it keeps
// every joint able to stop before its position limit, below its velocity
// limit and within its torque limit, whatever the QP returned (counted:
// lastStepGuarded, guardCount).
//
// Frames: world (design notes 1); spatial vectors [linear; angular]; SI.
// Real-time safety: step() and every set*/read-out method allocate nothing
// and never throw. The constructor and reset() are start-up calls.
#pragma once

#include <memory>
#include <string>

#include "control/constraints/joint_acceleration_limit.hpp"
#include "control/constraints/joint_position_limit.hpp"
#include "control/constraints/joint_torque_limit.hpp"
#include "control/constraints/joint_velocity_limit.hpp"
#include "control/controller_config.hpp"
#include "control/controller_registry.hpp"
#include "control/formulation/formulation.hpp"
#include "control/qp/qp_solver.hpp"
#include "control/qp/soft_row_relaxation.hpp"
#include "control/safety/limit_guard.hpp"
#include "control/tasks/end_effector_pose_task.hpp"
#include "control/tasks/grasp_frame.hpp"
#include "control/tasks/observation_task.hpp"
#include "control/tasks/observed_object_integrator.hpp"
#include "control/tasks/posture_task.hpp"
#include "control/tasks/trajectory_tracking_task.hpp"

namespace handover::control {

/// What the controller reads each period (from the arm's sensors).
struct ControlInputs {
  double time = 0.0;             ///< s
  Vector7 q = Vector7::Zero();   ///< rad
  Vector7 qd = Vector7::Zero();  ///< rad/s
};

class Controller {
 public:
  /// Copies the model. `solver` defaults to the Goldfarb-Idnani solver.
  /// Builds config.tasks and config.constraints with the shipped registry
  /// and no collision scene (a "collision" entry is skipped).
  /// Throws InputError / std::out_of_range on a config that does not fit the model.
  Controller(Model model, const ControllerConfig& config, std::unique_ptr<QpSolver> solver = nullptr);
  /// Same with `registry`'s types, and `collision` (may be null) for the
  /// constraints of type collision.
  Controller(Model model, const ControllerConfig& config, const ControllerRegistry& registry,
             const CollisionConfig* collision, std::unique_ptr<QpSolver> solver = nullptr);

  /// Starts from the arm state `in`: the observed object is placed so that
  /// its grasp frame coincides with the TCP (at rest), the observation and
  /// pose targets are set there, limit dampers and the warm start forgotten.
  void reset(const ControlInputs& in);

  /// One control period. Returns the joint torques (N m). Real-time safe.
  const Vector7& step(const ControlInputs& in);

  // -- commands (real-time safe) ------------------------------------------
  /// Measured object (or hand) pose in the world. Invalid or non-finite
  /// measurements are ignored: the last valid target is held.
  void setObservationTarget(const Isometry& pose, bool valid);
  /// Moves the observed object (e.g. when the observation switches target).
  void resetObservedObject(const Isometry& pose, const Vector6& velocity = Vector6::Zero());
  void setGraspOffset(const GraspOffset& offset);
  /// Task and constraint switches by name; false if the name is unknown.
  bool setTaskEnabled(const std::string& name, bool enabled);
  bool setConstraintEnabled(const std::string& name, bool enabled);
  void setPoseTarget(const Isometry& target) {
    if (pose_) pose_->setTarget(target);
  }
  void setPostureTarget(const Vector7& q_ref) {
    if (posture_) posture_->setTarget(q_ref);
  }

  // -- generic task handles (real-time safe but taskIndex) ------------------
  /// Index of the task named `name` in config.tasks order, -1 if none (start-up: compares strings).
  int taskIndex(const std::string& name) const;
  int numTasks() const { return static_cast<int>(tasks_.size()); }
  const Task& task(int index) const { return *tasks_[index]; }
  /// On / off (false for an invalid index).
  bool setTaskEnabled(int index, bool enabled);
  bool taskEnabled(int index) const;
  /// Target, gains, offset of a task (false: invalid index, or the task has no such notion).
  bool setTaskTarget(int index, const TaskTarget& target);
  bool setTaskGains(int index, const TaskGains& gains);
  /// The offset's free axis is normalised (none if it is zero or not finite).
  bool setTaskOffset(int index, const GraspOffset& offset);
  /// The built constraints in config.constraints order (a skipped entry is absent).
  const std::vector<std::shared_ptr<Constraint>>& constraints() const { return constraints_; }
  void setPayload(const Payload& payload);
  void clearPayload();
  /// The known external wrench f on the robot at the "ft_sensor" origin,
  /// [force (N); torque (N m)] in world axes (ContactWrenchEstimator::
  /// feedForward): the dynamics hold it, tau = M qddot + h - J_ft^T f, from
  /// the next step on. Non-finite input is ignored (the last value is kept).
  void setExternalWrench(const Vector6& wrench);
  const Vector6& externalWrench() const { return external_wrench_; }
  /// How much of the observed joint disturbance (DisturbanceObserver) the
  /// dynamics hold instead of the external wrench, 0..1 (clamped; always 0
  /// with config disturbance.compensation off):
  /// tau = M qddot + h - ((1 - g) J_ft^T f + g d). The caller passes the
  /// carry's ramp (ContactWrenchEstimator::disturbanceGain). `learn`: the
  /// observer updates its estimate (false holds it: a person may be touching).
  /// A gain that rises from 0 starts a new carry: the observer starts afresh,
  /// so a carry never inherits the last one's estimate. RT safe.
  void setDisturbanceFeedback(double gain, bool learn);
  /// Linear acceleration of the "ft_sensor" origin (world, m/s^2) the last
  /// step commanded: J qddot + Jdot qdot at its state.
  Vector3 sensorAcceleration() const;
  /// Scales the joint velocity limits by s in (0, 1] (clamped).
  void setSpeedScale(double s);

  // -- read-outs (real-time safe) -----------------------------------------
  const ObservedState& observedState() const { return integrator_.state(); }
  const Isometry& observationTarget() const { return observation_->target(); }
  bool hasValidObservation() const { return has_observation_; }
  /// Grasp frame pose / velocity / acceleration (last solved alphadot_obs).
  GraspFrameState graspFrame() const;
  Isometry tcpPose() const;
  Vector6 tcpVelocity() const;
  const Vector7& lastQdd() const { return qdd_; }
  const Vector7& lastTau() const { return tau_; }
  QpStatus lastStatus() const { return status_; }
  int lastIterations() const { return iterations_; }
  bool lastStepFellBack() const { return fell_back_; }
  /// Whether the last step's QP was solved only with its soft rows relaxed.
  bool lastStepRelaxed() const { return relaxed_; }
  /// Widening of the soft rows in the last step (0 when not relaxed; row units, m/s^2 for collision).
  double lastSlack() const { return slack_; }
  /// Steps solved with relaxed soft rows since reset().
  long relaxedCount() const { return relaxed_count_; }
  /// Whether the last step's QP was solved only at the full velocity limits
  /// (the speed scale lifted), and how many steps were since reset().
  bool lastStepUnslowed() const { return unslowed_; }
  long unslowedCount() const { return unslowed_count_; }
  long fallbackCount() const { return fallback_count_; }
  /// Consecutive fallback steps up to the last one (0 after a solved step):
  /// an application logs a fallback when this is 1 (and now and then after).
  long fallbackStreak() const { return fallback_streak_; }
  /// Whether the limit guard changed the last step's command (QP or fallback).
  bool lastStepGuarded() const { return guard_.lastChanged(); }
  /// Steps whose command the limit guard changed since reset().
  long guardCount() const { return guard_.changedCount(); }
  const LimitGuard& limitGuard() const { return guard_; }
  /// Why the last fallback happened ("" if no detail); static storage.
  const char* lastFallbackReason() const { return fallback_reason_; }
  /// [e_p (m); e_o (rad, or axis error in free-axis mode)] of the tracking task.
  const Vector6& trackingError() const { return tracking_->error(); }

  // -- access for tests, logging and additional tasks ---------------------
  const Model& model() const { return model_; }
  const Data& data() const { return data_; }
  const ControllerConfig& config() const { return config_; }
  Formulation& formulation() { return formulation_; }
  const Formulation& formulation() const { return formulation_; }
  const QpProblem& problem() const { return problem_; }
  QpSolver& solver() { return *solver_; }
  ObservationTask& observationTask() { return *observation_; }
  TrajectoryTrackingTask& trackingTask() { return *tracking_; }
  /// These need a task / constraint of that type in the config (the shipped one has them).
  PostureTask& postureTask() { return *posture_; }
  EndEffectorPoseTask& poseTask() { return *pose_; }
  JointPositionLimit& positionLimit() { return *position_limit_; }
  JointVelocityLimit& velocityLimit() { return *velocity_limit_; }

 private:
  void fallback(const char* why);
  void guardCommand();
  ControlContext context(double time) const;

  const Model model_;
  Data data_;
  ControllerConfig config_;
  Formulation formulation_;
  QpProblem problem_;
  std::unique_ptr<QpSolver> solver_;
  SoftRowRelaxation relaxation_;
  LimitGuard guard_;
  int tcp_id_ = 0;
  int ft_id_ = 0;
  Vector6 external_wrench_ = Vector6::Zero();
  Vector7 tau_external_ = Vector7::Zero();
  DisturbanceObserver disturbance_;
  double disturbance_gain_ = 0.0;
  bool disturbance_learn_ = true;
  Matrix6x7 J_ft_ = Matrix6x7::Zero();

  void build(const ControllerRegistry& registry, const CollisionConfig* collision);

  std::vector<std::shared_ptr<Task>> tasks_;              // config.tasks order
  std::vector<std::shared_ptr<Constraint>> constraints_;  // config.constraints order
  // the tasks and constraints the controller itself reads (found by type)
  std::shared_ptr<ObservationTask> observation_;
  std::shared_ptr<TrajectoryTrackingTask> tracking_;
  std::shared_ptr<PostureTask> posture_;        // may be null
  std::shared_ptr<EndEffectorPoseTask> pose_;   // may be null
  std::shared_ptr<JointPositionLimit> position_limit_;  // may be null
  std::shared_ptr<JointVelocityLimit> velocity_limit_;  // may be null

  ObservedObjectIntegrator integrator_;
  bool has_observation_ = false;
  double time_ = 0.0;

  Eigen::VectorXd x_;                  // kNumVars
  Eigen::MatrixXd obs_A_;              // 6 x kNumVars scratch (fallback observation law)
  Eigen::VectorXd obs_b_;              // 6
  Vector7 qdd_ = Vector7::Zero();
  Vector7 tau_ = Vector7::Zero();
  QpStatus status_ = QpStatus::kOptimal;
  int iterations_ = 0;
  bool fell_back_ = false;
  bool relaxed_ = false;
  bool unslowed_ = false;
  double slack_ = 0.0;
  long relaxed_count_ = 0;
  long unslowed_count_ = 0;
  long fallback_count_ = 0;
  long fallback_streak_ = 0;
  const char* fallback_reason_ = "";
};

}  // namespace handover::control
