// What the handover states may ask of the controller. The QP controller
// implements it through an adapter (written on the control side); tests use a
// recording fake. Every call only stores a set-point that the controller
// applies at its next solve, so calls must be cheap and real-time safe
// (no allocation, no I/O, no blocking).
//
// Frames and units: world frame (z up, base at the origin), SI units; poses
// are Eigen::Isometry3d; joint vectors are the 7 arm joints in chain order.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

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
};

/// Which sensed body the observation task follows.
enum class ObservationTarget { kNone, kObject, kHand };
const char* toString(ObservationTarget target);

class ControllerInterface {
 public:
  virtual ~ControllerInterface() = default;

  // --- QP configuration (scoped: a state that changes one undoes it) ------
  /// Observation task reference: the sensed object, the person's hand, or
  /// none (the observed frame then coasts to rest).
  virtual void setObservationTarget(ObservationTarget target) = 0;
  /// Turns the trajectory-tracking task (end effector follows the target
  /// frame derived from the observed frame) on or off.
  virtual void enableTracking(bool on) = 0;
  /// Target frame of the tracking task expressed in the observed frame: the
  /// grasp frame in the object frame (human to robot), or the TCP pose in
  /// the hand frame that puts the object in the hand (robot to human).
  virtual void setTrackingOffset(const TrackingOffset& offset) = 0;
  /// Set-point for the TCP (world frame): retract, stow, safe or hold pose.
  virtual void setPoseTarget(const Isometry& tcp_in_world) = 0;
  virtual void clearPoseTarget() = 0;
  /// Reference of the posture task (rad); clear returns to the default.
  virtual void setPostureTarget(const Vector7& q) = 0;
  virtual void clearPostureTarget() = 0;
  /// Scales every task's speed (0 = hold still, 1 = nominal).
  virtual void setSpeedScale(double scale) = 0;
  /// Stiffness of the tracking task (1/s^2, translation and orientation,
  /// critically damped) for the current phase; clear returns to the
  /// configured gains. Optional: a controller without phase gains ignores it.
  virtual void setTrackingStiffness(double translation, double orientation) {
    (void)translation;
    (void)orientation;
  }
  virtual void clearTrackingStiffness() {}
  /// While the person's hand and the gripper share the object (closing on
  /// it, waiting for the release, being pulled), the clearance kept between
  /// the person's hand and the gripper is switched off; every other person
  /// and self-collision clearance stays. Optional (default: ignored).
  virtual void relaxHandClearance(bool relaxed) { (void)relaxed; }

  // --- physical commands (persistent: they outlive the state) -------------
  /// Total finger opening target (m, 0..0.08) and grasp force limit (N).
  virtual void setGripper(double width, double force) = 0;
  /// Object held by the gripper: mass (kg) and centre of mass in the TCP
  /// frame (m), for the dynamics and gravity compensation.
  virtual void setPayload(double mass, const Vector3& com_in_tcp) = 0;
  virtual void clearPayload() = 0;
};

}  // namespace handover::fsm
