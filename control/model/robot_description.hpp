// The robot description: together with the URDF, everything the code knows
// about the arm that the URDF does not say (config/robot.yaml for
// the Panda). Code outside the description names no joint or link of a
// particular robot: it reads the names, roles and limits from here.
//
//   urdf                 path of the URDF (relative to the description file)
//   base_link            link the 7-joint chain is walked from (fixed base)
//   frames               links behind the aliases "hand", "tcp", "ft_sensor"
//   capsule_prefix       stripped from a link name to name its capsules
//                        ("<prefix>link3" -> "link3", two on a link: "_a", "_b")
//   acceleration_limits  rad/s^2, joints in chain order (a URDF has none)
//   gripper.links        links whose capsules are the gripper (hand, fingers)
//   gripper.fingers      the two finger links, left then right (each one of
//                        gripper.links; the simulator's contact report and
//                        finger joints: the URDF cannot say which is left)
//   gripper.fingertip_capsules  gripper capsules that reach around the object
//   link_groups          named groups of links ("arm", "gripper", "wrist", ...)
//                        that config/collision.yaml's pair rules name
//
// The DoF is fixed at compile time (kArmDofs = 7): another 7-DoF arm is a
// description change; a different DoF is not. Start-up only (reads a file,
// allocates, throws InputError naming the file, key and line).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "control/model/link_group.hpp"
#include "control/types.hpp"

namespace handover::control {

struct RobotDescription {
  std::string file;            ///< where it was read ("" for a built one)
  std::string urdf;            ///< URDF path (resolved against the description's folder)
  std::string base_link;
  std::string hand_link;       ///< behind the frame alias "hand"
  std::string tcp_link;        ///< behind the frame alias "tcp" (the grasp point)
  std::string ft_sensor_link;  ///< behind the frame alias "ft_sensor"
  std::string capsule_prefix;
  Vector7 acceleration_limits = Vector7::Zero();  ///< rad/s^2
  std::vector<std::string> gripper_links;
  std::array<std::string, 2> finger_links;  ///< left, right (each in gripper_links)
  std::vector<std::string> fingertip_capsules;
  std::vector<LinkGroup> link_groups;  ///< in file order
};

/// Reads a description with the strict YAML reader: every key required,
/// unknown keys rejected, limits > 0.
RobotDescription loadRobotDescription(const std::string& path);
/// HANDOVER_SOURCE_DIR/config/robot.yaml.
std::string defaultRobotDescriptionPath();
/// The default description, read once per call (start-up only).
RobotDescription defaultRobotDescription();

}  // namespace handover::control
