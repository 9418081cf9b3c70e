// Plain structs between the controller side and the simulator (or a real
// robot driver). The controller never sees mjModel/mjData (Drake /
// ros2_control style): state in, command out.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace handover::sim {

using Vector7 = Eigen::Matrix<double, 7, 1>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

/// What the arm's own sensors report each 1 ms step.
struct ArmState {
  double time = 0.0;                 ///< s since the start of the run
  Vector7 q = Vector7::Zero();       ///< joint positions, rad
  Vector7 qd = Vector7::Zero();      ///< joint velocities, rad/s
  Vector7 tau_measured = Vector7::Zero();  ///< applied joint torques, N m
  double finger_width = 0.0;         ///< total opening between the fingers, m
  /// Wrist force-torque sensor, [force (N); torque (N m)] that the hand exerts
  /// on the flange... expressed in the "ft_sensor" frame. With an empty hand at
  /// rest it reads the hand's own weight; see docs for the sign convention.
  Vector6 wrench = Vector6::Zero();
};

/// What the controller sends each 1 ms step.
struct ArmCommand {
  Vector7 tau = Vector7::Zero();     ///< joint torques, N m (clamped to the limits by the simulator)
  double gripper_width = 0.08;       ///< total finger opening target, m (0 = close fully)
  double gripper_force = 70.0;       ///< grasp force limit, N
};

/// World poses of the person's kinematic bodies (set by the scripted human).
struct HumanBodyPoses {
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();       ///< grip point frame (design notes 1)
  Eigen::Isometry3d forearm = Eigen::Isometry3d::Identity();    ///< origin at the elbow, z along elbow->wrist
  Eigen::Isometry3d upper_arm = Eigen::Isometry3d::Identity();  ///< origin at the shoulder, z along shoulder->elbow
  Eigen::Isometry3d torso = Eigen::Isometry3d::Identity();      ///< origin on the floor under the body centre, x forward
  double forearm_length = 0.27;    ///< m, elbow to wrist
  double upper_arm_length = 0.33;  ///< m, shoulder to elbow
};

/// Physical facts of one step that judges and the scripted person use.
struct ContactReport {
  int robot_human = 0;              ///< contacts between robot geoms and the person's geoms
  bool left_finger_on_object = false;
  bool right_finger_on_object = false;
  bool object_on_table = false;     ///< object touches the table
  bool object_on_floor = false;
  bool object_welded_to_hand = false;
};

/// Ground truth of the object (for judging and sensors; not for the controller).
struct ObjectState {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< object frame in the world
  Vector6 velocity = Vector6::Zero();   ///< [linear; angular], world axes
};

}  // namespace handover::sim
