// The person's trunk (legs, torso, head, and the other arm hanging beside it
// on the side opposite the handing hand) for the controller's collision
// scene, sized from the scenario's stature exactly as the simulated scene
// sizes its torso body (scenes/scenario/body_dimensions.hpp). Torso frame:
// origin on the floor under the body centre, x forward, z up; m. Pure.
#pragma once

#include "control/collision/collision_config.hpp"
#include "scenes/scenario/body_dimensions.hpp"

namespace handover::app {

inline control::PersonTrunk personTrunkFor(const scenario::BodyDimensions& b, scenario::HandSide handing) {
  control::PersonTrunk t;
  t.torso_size = control::Vector3(b.torso_depth, b.torso_width, b.torso_top - b.hip_height);
  t.torso_centre = 0.5 * (b.torso_top + b.hip_height);
  t.legs_size = control::Vector3(b.legs_depth, b.legs_width, b.hip_height);
  t.legs_centre = 0.5 * b.hip_height;
  t.head_radius = b.head_radius;
  t.head_centre = b.head_centre;
  // the other arm hangs beside the torso, one capsule from the shoulder to the fingertips
  const scenario::HangingArm free_arm = scenario::freeArmInTorso(b, handing);
  t.free_arm_top = free_arm.shoulder;
  t.free_arm_bottom = free_arm.tip;
  return t;
}

}  // namespace handover::app
