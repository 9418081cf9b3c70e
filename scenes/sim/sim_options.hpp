// What can be chosen when the simulated world is loaded: the scene file, the
// object (shape, size, mass, friction) and the person's body dimensions.
// Sizes follow the scenario convention (design notes section 2), not
// MuJoCo's half-sizes: the scene builder converts.
#pragma once

#include <string>
#include <vector>

#include "scenes/scenario/body_dimensions.hpp"

namespace handover::sim {

enum class ObjectShape { Cylinder, Box, Sphere };

/// "cylinder" | "box" | "sphere"; throws handover::InputError naming `key` otherwise.
ObjectShape parseObjectShape(const std::string& text, const std::string& key = "object.shape");
const char* toString(ObjectShape shape);

struct ObjectOptions {
  ObjectShape shape = ObjectShape::Cylinder;
  /// cylinder [radius, height]; box [x, y, z] full edge lengths; sphere [radius]; m
  std::vector<double> size = {0.035, 0.20};
  double mass = 0.3;       ///< kg
  double friction = 1.0;   ///< sliding friction coefficient (MuJoCo takes the max of the pair)
};

/// The person's dimensions. Segment lengths can also change at run time
/// through HumanBodyPoses (sim_io.hpp); these are the values at load.
struct HumanOptions {
  double height = 1.75;            ///< m, stature (sizes legs, torso, head)
  double upper_arm_length = 0.33;  ///< m, shoulder to elbow
  double forearm_length = 0.27;    ///< m, elbow to wrist
  /// the handing (tracked) hand; the other arm hangs beside the torso
  scenario::HandSide hand = scenario::HandSide::Right;
};

struct SimOptions {
  std::string scene_path;  ///< MJCF template; empty = <source dir>/scenes/handover_scene.xml
  /// The robot description whose names the scene holds (control/model/
  /// robot_description.hpp); empty = <source dir>/config/robot.yaml
  std::string robot_description;
  ObjectOptions object;
  HumanOptions human;
};

/// <source dir>/scenes/handover_scene.xml
std::string defaultScenePath();

/// Checks sizes, masses and lengths (finite, positive, right count for the
/// shape); throws handover::InputError naming the option and the value.
void validate(const SimOptions& options);

}  // namespace handover::sim
