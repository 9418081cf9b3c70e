// The simulated world's facts (contacts, the object's ground truth), kept
// apart from arm I/O (interfaces/arm_io.hpp), which the simulator shares
// with any robot driver. The controller never sees mjModel/mjData.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "interfaces/arm_io.hpp"
#include "interfaces/human_body_poses.hpp"

namespace handover::sim {

using Vector7 = Eigen::Matrix<double, 7, 1>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

/// Arm I/O and the person's body poses are neutral types (interfaces/);
/// the simulator's spellings stay for its callers.
using ArmState = io::ArmState;
using ArmCommand = io::ArmCommand;
using HumanBodyPoses = io::HumanBodyPoses;

/// Physical facts of one step that judges and the scripted person use.
struct ContactReport {
  int robot_human = 0;              ///< contacts between robot geoms and the person's geoms
  bool left_finger_on_object = false;
  bool right_finger_on_object = false;
  bool object_on_table = false;     ///< object touches the table
  bool object_on_floor = false;
  bool object_welded_to_hand = false;
};

/// True clearance between the simulated robot's collision geoms and the
/// person's geoms (hand, forearm, upper arm, torso, legs, head), from
/// MuJoCo's own geometry at the state contacts() describes. m; negative =
/// penetration depth. Distances above the query's cap read as the cap.
struct PersonClearance {
  double all = 0.0;              ///< every robot geom, fingers included
  double without_fingers = 0.0;  ///< the finger geoms left out (they hold a shared object)
};

/// Ground truth of the object (for judging and sensors; not for the controller).
struct ObjectState {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< object frame in the world
  Vector6 velocity = Vector6::Zero();   ///< [linear; angular], world axes
};

}  // namespace handover::sim
