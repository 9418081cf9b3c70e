// A named group of robot links, declared by the robot description
// (config/robot.yaml `link_groups`) so that other files (config/collision.yaml)
// name parts of the arm by role ("gripper", "wrist") instead of by link.
// Start-up data; not used in the control step.
#pragma once

#include <string>
#include <vector>

namespace handover::control {

struct LinkGroup {
  std::string name;                   ///< e.g. "gripper"
  std::vector<std::string> patterns;  ///< link or capsule names; '*' and '?' are wildcards
};

}  // namespace handover::control
