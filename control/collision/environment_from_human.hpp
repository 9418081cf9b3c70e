// Converts the person's body poses (io::HumanBodyPoses: a tracker's or the simulator's)
// into a CollisionEnvironment. Real-time safe. Velocities stay zero: the
// poses carry none; a caller with estimates can fill them in afterwards.
#pragma once

#include "control/collision/collision_environment.hpp"
#include "interfaces/human_body_poses.hpp"

namespace handover::control {

inline CollisionEnvironment environmentFromHuman(const io::HumanBodyPoses& person, bool valid = true) {
  CollisionEnvironment env;
  env.person_valid = valid;
  env.hand = person.hand;
  env.forearm = person.forearm;
  env.upper_arm = person.upper_arm;
  env.torso = person.torso;
  env.trunk_valid = valid;
  env.forearm_length = person.forearm_length;
  env.upper_arm_length = person.upper_arm_length;
  return env;
}

}  // namespace handover::control
