// What the handover states may ask of the controller. The QP controller
// implements it through an adapter (written on the control side); tests use a
// recording fake. Tasks are addressed through generic handles (a task's
// name in config/controller.yaml, then enable / target / gains / offset),
// so a new task needs no new call here. Every call only stores a set-point
// that the controller applies at its next solve, so calls must be cheap and
// real-time safe (no allocation, no I/O, no blocking); taskHandle is a
// start-up call.
//
// Frames and units: world frame (z up, base at the origin), SI units; poses
// are Eigen::Isometry3d; joint vectors are the 7 arm joints in chain order.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

namespace handover::fsm {

using Isometry = Eigen::Isometry3d;
using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Vector7 = Eigen::Matrix<double, 7, 1>;

/// Target frame of the tracking task in the observed frame. `planned`: the
/// frame is a choice the grasp planner made with the robot's kinematics (a
/// reachable turn about the object's free axis, or a gripper twin), to be
/// tracked exactly; otherwise the controller may still turn it about the
/// object's free axis and pick the gripper's half-turn twin itself.
struct TrackingOffset {
  Isometry target_in_observed = Isometry::Identity();
  bool planned = false;
  /// With `planned`: the configuration the planner found for that frame (rad),
  /// the way a large turn goes (control::GraspOffset::joint_plan).
  Vector7 joint_plan = Vector7::Zero();
  /// The frame sliding along its own z (a standoff shrinking: positive), m/s
  /// and m/s^2: fed forward to the tracking (control::GraspOffset::approach_speed).
  double approach_speed = 0.0;
  double approach_acceleration = 0.0;
};

/// A task's reference for setTaskTarget: the one it was configured with, a
/// pose (world frame) or joint positions (rad, chain order).
struct TaskTarget {
  enum class Kind { kConfigured, kPose, kJoints };
  Kind kind = Kind::kConfigured;
  Isometry pose = Isometry::Identity();
  Vector6 velocity = Vector6::Zero();  ///< kPose: the pose's own motion [m/s; rad/s], world axes
  Vector7 q = Vector7::Zero();
  Vector7 qd = Vector7::Zero();   ///< kJoints: the joints' reference velocity, rad/s (fed forward)
  Vector7 qdd = Vector7::Zero();  ///< kJoints: ... and acceleration, rad/s^2
};

/// A task's gains for setTaskGains: inactive = the configured gains; else
/// critically damped stiffnesses (1/s^2) for translation and orientation,
/// and (tracking task) the fastest the PD may ask the frame to close in.
struct TaskGains {
  bool active = false;
  double translation = 0.0;
  double orientation = 0.0;
  double max_speed = 0.0;  ///< m/s; 0 = the task's configured limit
};

/// Which sensed body the observation task follows.
enum class ObservationTarget { kNone, kObject, kHand };
const char* toString(ObservationTarget target);

class ControllerInterface {
 public:
  virtual ~ControllerInterface() = default;

  // --- the controller's tasks, by name (scoped through the ledger) --------
  /// Handle of the task named `name` in the controller's config
  /// (config/controller.yaml `tasks:`, e.g. "tracking", "pose", "posture"),
  /// -1 when it has none (the calls below then do nothing). Start-up: the
  /// ledger resolves its handles once.
  virtual int taskHandle(const std::string& name) const = 0;
  /// Turns a task on or off (e.g. "tracking": the end effector follows the
  /// target frame derived from the observed frame).
  virtual void setTaskEnabled(int task, bool on) = 0;
  /// Back to the state the config gives it (`enabled:` of its entry).
  virtual void resetTaskEnabled(int task) = 0;
  /// A task's reference (e.g. the TCP set-point of "pose", world frame; the
  /// joints of "posture"); kConfigured returns to the configured one.
  virtual void setTaskTarget(int task, const TaskTarget& target) = 0;
  /// A task's gains for the current phase (e.g. "tracking"); inactive
  /// returns to the configured gains.
  virtual void setTaskGains(int task, const TaskGains& gains) = 0;
  /// A task's frame in the observed frame (e.g. "tracking": the grasp frame
  /// in the object frame, human to robot, or the TCP pose in the hand frame
  /// that puts the object in the hand, robot to human).
  virtual void setTaskOffset(int task, const TrackingOffset& offset) = 0;

  // --- QP configuration that is not a task (scoped) ------------------------
  /// Observation task reference: the sensed object, the person's hand, or
  /// none (the observed frame then coasts to rest).
  virtual void setObservationTarget(ObservationTarget target) = 0;
  /// Scales every task's speed (0 = hold still, 1 = nominal).
  virtual void setSpeedScale(double scale) = 0;
  /// While the person's hand and the gripper share the object (closing on
  /// it, waiting for the release, being pulled), the clearance kept between
  /// the person's hand and the gripper is switched off; every other person
  /// and self-collision clearance stays. Optional (default: ignored).
  virtual void relaxHandClearance(bool relaxed) { (void)relaxed; }
  /// The fingers are around the object the person holds (closed on it,
  /// waiting for the release). The clearances of a gripper that comes for
  /// the object are off: the one kept from the object itself, and the one the
  /// closing fingers keep from the person's hand (collision rules `when:
  /// taking`). The fingers cannot leave the hand without the object: against
  /// a hand that touched them the wrist turned at its speed limit instead
  /// (g1097_00374). Optional (default: ignored).
  virtual void fingersAroundObject(bool around) { (void)around; }
  /// The observation target (and the grasp planning) read where the person's
  /// reaching hand will come to rest (perception/reach_predictor.hpp) instead
  /// of where it is: the arm goes to meet the object where it will stop.
  /// Optional (default: ignored).
  virtual void anticipateRest(bool on) { (void)on; }

  // --- the observed frame (unscoped; optional: the defaults do nothing) ---
  /// Puts the observed frame (the observation task's state) at `pose`
  /// (world) at rest, and the observation task's target with it until the
  /// next measurement: the observed frame starts there instead of converging
  /// to it (e.g. on the first sample of the object).
  virtual void placeObservedFrame(const Isometry& pose) { (void)pose; }
  /// The TCP pose (world) the tracking task's offset asks for while the
  /// observed frame rests at `observed` (world), resolved by the controller's
  /// own rule (the free-axis turn and the gripper twin nearest the TCP's
  /// current orientation and the wrist joint at `wrist_q`, rad); e.g. a pose
  /// task's set-point on a measured object. False when unavailable.
  virtual bool trackingTargetAt(const Isometry& observed, double wrist_q, Isometry& tcp) const {
    (void)observed;
    (void)wrist_q;
    (void)tcp;
    return false;
  }

  // --- physical commands (persistent: they outlive the state) -------------
  /// Total finger opening target (m, 0..0.08) and grasp force limit (N).
  virtual void setGripper(double width, double force) = 0;
  /// Object held by the gripper: mass (kg) and centre of mass in the TCP
  /// frame (m), for the dynamics and gravity compensation.
  virtual void setPayload(double mass, const Vector3& com_in_tcp) = 0;
  virtual void clearPayload() = 0;
};

}  // namespace handover::fsm
