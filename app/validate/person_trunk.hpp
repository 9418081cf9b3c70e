// The person's trunk (legs, torso, head) for the controller's collision
// scene, sized from the scenario's stature exactly as the simulated scene
// sizes its torso body (scenes/scenario/body_dimensions.hpp). Torso frame:
// origin on the floor under the body centre, x forward, z up; m. Pure.
#pragma once

#include "control/collision/collision_config.hpp"
#include "scenes/scenario/body_dimensions.hpp"

namespace handover::app {

inline control::PersonTrunk personTrunkFor(const scenario::BodyDimensions& b) {
  control::PersonTrunk t;
  t.torso_size = control::Vector3(b.torso_depth, b.torso_width, b.torso_top - b.hip_height);
  t.torso_centre = 0.5 * (b.torso_top + b.hip_height);
  t.legs_size = control::Vector3(b.legs_depth, b.legs_width, b.hip_height);
  t.legs_centre = 0.5 * b.hip_height;
  t.head_radius = b.head_radius;
  t.head_centre = b.head_centre;
  return t;
}

}  // namespace handover::app
