// Rigid-body model of the Panda arm (Model/Data split, as in Pinocchio).
//
// Model: const, built once from the robot description (URDF + a small YAML,
//        robot_description.hpp) by loadModel().
// Data:  preallocated scratch written by the algorithms in algorithms.hpp.
//
// Bodies: index 0 = link0 (fixed base, at the world origin), index i = link i
// (i = 1..7, moved by joint i). The hand and both fingers are fixed to link 7
// (fingers at Model::finger_opening) and merged into body 7's inertia for the
// dynamics; their frames stay available by name.
// Units: SI. Frames: world z up, base at the origin (design-notes section 1).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "control/model/link_group.hpp"
#include "control/types.hpp"

namespace handover::control {

constexpr int kNumBodies = kArmDofs + 1;  ///< link0..link7

/// Mass properties of a body, expressed in that body's frame.
struct Inertia {
  double mass = 0.0;                          ///< kg
  Vector3 com = Vector3::Zero();              ///< centre of mass in the body frame, m
  Matrix3 inertia_com = Matrix3::Zero();      ///< rotational inertia about the com, body axes, kg m^2
};

/// A named frame rigidly attached to a body (e.g. "tcp", "ft_sensor", "hand").
struct Frame {
  std::string name;
  int body = 0;                               ///< 0..7
  Isometry placement = Isometry::Identity();  ///< frame pose in the body frame
};

/// What a capsule is to the handover: part of the arm, of the gripper (its
/// clearance to the person's hand is scoped by the state machine), or the
/// gripper's fingertip capsule that closes on the object. From the robot
/// description (gripper.links, gripper.fingertip_capsules).
enum class CapsuleRole { kArm, kGripper, kFingertip };

/// A collision capsule: segment [a, b] swept by a sphere of `radius`, in the
/// frame of body `body` (0..7). Fixed children (hand, fingers) are attached to
/// body 7 with their points already transformed into link 7's frame.
struct Capsule {
  std::string name;    ///< e.g. "link3", "hand_a"
  std::string link;    ///< URDF link it came from
  CapsuleRole role = CapsuleRole::kArm;  ///< kFingertip is also a gripper capsule
  int body = 0;
  Vector3 a = Vector3::Zero();  ///< m, body frame
  Vector3 b = Vector3::Zero();  ///< m, body frame
  double radius = 0.0;          ///< m
};

struct Model {
  std::string urdf_path;
  std::array<std::string, kNumBodies> body_names;       ///< URDF link names
  std::array<std::string, kArmDofs> joint_names;        ///< URDF joint names, chain order
  std::array<Isometry, kArmDofs> joint_placements;      ///< joint i frame in body i-1's frame at q_i = 0
  std::array<Vector3, kArmDofs> joint_axes;             ///< unit axis of joint i in its own frame
  std::array<Inertia, kNumBodies> inertias;             ///< body inertias (body 7 includes hand + fingers)
  /// What hangs below the wrist force-torque sensor (the hand link and
  /// everything fixed to it, fingers at finger_opening), in the "ft_sensor"
  /// frame: the F/T bias model subtracts its weight (control/wrench).
  Inertia tool;
  Vector7 q_min, q_max;        ///< rad
  Vector7 v_max;               ///< rad/s
  Vector7 a_max;               ///< rad/s^2 (datasheet qdd_max)
  Vector7 tau_max;             ///< N m
  Vector3 gravity = Vector3(0.0, 0.0, -9.81);  ///< m/s^2, world frame
  double finger_opening = 0.08;   ///< m, total opening at which finger inertia is merged
  double finger_max_opening = 0.08;  ///< m, total
  std::vector<Frame> frames;      ///< named frames (every link, "hand", "tcp", "ft_sensor", fingers)
  std::vector<Capsule> capsules;  ///< collision geometry
  /// Named link groups of the robot description (config/robot.yaml
  /// link_groups): what config/collision.yaml's rules name.
  std::vector<LinkGroup> link_groups;

  /// Index into `frames`; throws std::out_of_range naming the frame if absent.
  int frameId(const std::string& name) const;
  bool hasFrame(const std::string& name) const;
};

struct RobotDescription;

/// Loads the model from a URDF with the names of a robot description
/// (robot_description.hpp). Throws handover::InputError whose message names
/// the file and what is wrong (missing file, parse error, a joint or link
/// that is not where the description's chain needs it, missing limits).
/// The chain is walked from the description's base_link through one revolute
/// joint per body; everything below link 7 must hang on fixed joints or the
/// two prismatic finger joints (set to finger_opening / 2 each, m total,
/// clamped to 0..max). Frames: every URDF link by name, plus the aliases
/// "hand", "tcp" and "ft_sensor" (the description's frames), which must
/// exist. Collision <cylinder>s are read as capsules
/// (docs/robot-description.md), their roles set from the description; a_max
/// is the description's acceleration_limits (URDF has none).
/// Not real-time safe (reads files, allocates).
Model loadModel(const std::string& urdf_path, const RobotDescription& description, double finger_opening);
/// The description's own URDF.
Model loadModel(const RobotDescription& description, double finger_opening);
/// This URDF with the default description's names (config/robot.yaml).
Model loadModel(const std::string& urdf_path);
Model loadModel(const std::string& urdf_path, double finger_opening);

/// A rigid payload held by the gripper (the object), attached to body 7.
struct Payload {
  double mass = 0.0;                       ///< kg
  Vector3 com = Vector3::Zero();           ///< in the "tcp" frame, m
  Matrix3 inertia_com = Matrix3::Zero();   ///< about the com, tcp axes, kg m^2
};

/// Per-cycle scratch. Sized once by the constructor; the algorithms never
/// allocate. One Data per thread.
struct Data {
  explicit Data(const Model& model);

  Vector7 q = Vector7::Zero();    ///< last configuration given to computeAll / forwardKinematics, rad
  Vector7 v = Vector7::Zero();    ///< last joint velocity, rad/s

  std::array<Isometry, kNumBodies> oMb;       ///< world pose of each body
  std::array<Matrix6x7, kNumBodies> body_jacobian;  ///< [v_origin; omega] of each body origin, world axes
  std::array<Vector6, kNumBodies> body_velocity;    ///< [v_origin; omega], world axes
  std::array<Vector6, kNumBodies> body_drift;       ///< classical accel [a_origin; omegadot] at qddot = 0, world axes

  Matrix7 M = Matrix7::Zero();    ///< joint-space mass matrix (CRBA), incl. payload
  Vector7 h = Vector7::Zero();    ///< bias torques: Coriolis + centrifugal + gravity (RNEA, qddot = 0), incl. payload
  Vector7 g = Vector7::Zero();    ///< gravity torques alone

  bool has_payload = false;
  Inertia body7_with_payload;     ///< body 7 inertia + payload, refreshed by setPayload / clearPayload

  // written by forwardKinematics, read by crba / rnea
  std::array<Vector3, kNumBodies> axis_world;       ///< joint i's unit axis in world axes (index 0 unused)
  std::array<Vector3, kNumBodies> com_world;        ///< body com in the world (body 7 incl. payload), m
  std::array<Matrix3, kNumBodies> inertia_world;    ///< body inertia about its com, world axes, kg m^2

  // internal scratch for the algorithms (RNEA/CRBA); sized here, reused
  std::array<Vector6, kNumBodies> scratch_v, scratch_a, scratch_f;
  std::array<Matrix6, kNumBodies> scratch_I;
};

}  // namespace handover::control
