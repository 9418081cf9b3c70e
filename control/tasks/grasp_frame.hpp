// The grasp frame rigidly attached to the observed object (paper eqs. forward
// position / velocity / acceleration), and the "nearest grasp" rule for
// objects that are symmetric about an axis. Real-time safe.
//
// Frames: X_grasp^obs is the grasp frame in the observed object's frame; all
// outputs are world axes, spatial vectors [linear; angular].
#pragma once

#include "control/formulation/control_context.hpp"

namespace handover::control {

/// Where the gripper grasps the object, in the object's frame.
struct GraspOffset {
  Isometry placement = Isometry::Identity();  ///< X_grasp^obs
  /// When true, the object is symmetric about `free_axis` (unit, object
  /// frame): any rotation of the grasp about that axis (through the object
  /// origin) is as good, and the one nearest to the gripper is used.
  bool has_free_axis = false;
  Vector3 free_axis = Vector3::UnitZ();
  /// With a free axis: instead of the rotation nearest to the gripper's
  /// orientation, pick the one whose approach axis (grasp z) points most along
  /// the horizontal-to-the-axis direction from `base` (world, m; the robot's
  /// base) to the object, so the gripper comes from the robot's side; the
  /// tracking task then controls all three orientation rows toward it.
  bool approach_from_base = false;
  Vector3 base = Vector3::Zero();
  /// A parallel-jaw gripper grasps the same way after a half turn about its
  /// approach axis (grasp z): of the grasp orientation and its half-turned
  /// twin, track the one that leaves the last (wrist) joint nearest the
  /// middle of its range (the tool axis is that joint's axis, so a turn phi
  /// about it moves the joint by phi). Only for an empty gripper (a held
  /// object would turn with it). Points keep their place: the lever arm is
  /// computed from the unturned frame.
  bool parallel_gripper = false;
  /// The configuration the grasp planner found for this grasp (rad), when it
  /// found one. A large turn to the grasp orientation then goes the way the
  /// joints move toward it, which may be the long way round: the shortest
  /// rotation can wind the wrist into its limit where the plan turns it the
  /// other way (TrajectoryTrackingTask).
  bool has_joint_plan = false;
  Vector7 joint_plan = Vector7::Zero();
  /// The placement sliding along its own approach axis (grasp z) as the state
  /// machine's standoff shrinks or grows: m/s and m/s^2 toward +z. Fed
  /// forward into the grasp frame's velocity and acceleration, so the TCP
  /// slides with the moving target instead of lagging it by D v / K (10 cm
  /// at 0.4 m/s and K = 60) and then closing the gap with the PD's slow tail.
  double approach_speed = 0.0;
  double approach_acceleration = 0.0;
};

struct GraspFrameState {
  Isometry pose = Isometry::Identity();    ///< X_grasp in the world
  Vector6 velocity = Vector6::Zero();      ///< [Pdot_grasp; omega_obs]
  Vector6 acceleration = Vector6::Zero();  ///< [Pddot_grasp; omegadot_obs]
  Vector3 lever = Vector3::Zero();         ///< r = P_grasp - P_obs, m, world axes
};

/// Rotation of the grasp frame in the world. Without a free axis: R_obs R_grasp^obs.
/// With one: a member of {R_obs Rot(free_axis, phi) R_grasp^obs}: with
/// approach_from_base the one facing away from the base (closed form), else
/// the one closest to R_ee (the smallest rotation that carries R_ee's copy of
/// the axis onto the object's axis, applied to R_ee).
Matrix3 graspRotation(const ObservedState& obs, const GraspOffset& offset, const Matrix3& R_ee);

/// Full state of the grasp frame given the observed object's state and its
/// acceleration `alphadot_obs` (use obs.acceleration for the last solved one).
/// R_ee picks the nearest grasp when the offset has a free axis (rotation about
/// it is frozen for this evaluation).
/// `wrist_angle`: the wrist joint's angle from the middle of its range (rad),
/// used only to pick a parallel-gripper twin. The placement's slide along the
/// grasp z (offset.approach_speed, approach_acceleration) adds to the
/// velocity and acceleration, with its Coriolis term 2 omega_obs x v_slide.
GraspFrameState graspFrameState(const ObservedState& obs, const Vector6& alphadot_obs, const GraspOffset& offset,
                                const Matrix3& R_ee, double wrist_angle = 0.0);

}  // namespace handover::control
