// Shared fixtures of the collision tests: the repository's Panda model, random
// configurations inside the joint limits, a person near the robot.
#pragma once

#include <random>
#include <string>

#include "control/collision/collision_config.hpp"
#include "control/collision/collision_environment.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"

namespace handover::control::testing {

inline const Model& pandaModel() {
  static const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  return model;
}

inline Vector7 readyPose() {
  Vector7 q;
  q << 0.0, -M_PI / 4, 0.0, -3 * M_PI / 4, 0.0, M_PI / 2, M_PI / 4;
  return q;
}

/// Uniform inside the limits, 5 % away from them.
inline Vector7 randomConfiguration(const Model& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.05, 0.95);
  Vector7 q;
  for (int i = 0; i < kArmDofs; ++i) q[i] = m.q_min[i] + u(rng) * (m.q_max[i] - m.q_min[i]);
  return q;
}

inline Vector7 randomVelocity(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Vector7 v;
  for (int i = 0; i < kArmDofs; ++i) v[i] = u(rng);
  return v;
}

inline Isometry randomRotation(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Isometry X = Isometry::Identity();
  X.linear() = Quaternion(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
  return X;
}

/// A person whose hand is at `hand_pos`, forearm and upper arm hanging back
/// toward +x (where the person stands), random orientations.
inline CollisionEnvironment personAt(const Vector3& hand_pos, std::mt19937& rng) {
  CollisionEnvironment env;
  env.person_valid = true;
  env.hand = randomRotation(rng);
  env.hand.translation() = hand_pos;
  const Vector3 wrist = hand_pos + Vector3(0.06, 0.0, 0.0);
  const Vector3 elbow = wrist + Vector3(0.22, 0.08, -0.12);
  const Vector3 shoulder = elbow + Vector3(0.1, 0.05, 0.3);
  auto along = [](const Vector3& from, const Vector3& to) {
    Isometry X = Isometry::Identity();
    X.translation() = from;
    X.linear() = Quaternion::FromTwoVectors(Vector3::UnitZ(), to - from).toRotationMatrix();
    return X;
  };
  env.forearm = along(elbow, wrist);
  env.forearm_length = (wrist - elbow).norm();
  env.upper_arm = along(shoulder, elbow);
  env.upper_arm_length = (elbow - shoulder).norm();
  return env;
}

/// Every robot capsule of the arm against table, person and the base links,
/// with a large iDist so that nothing is culled.
inline CollisionConfig wideConfig() {
  return parseCollisionConfig(R"(
broadphase_margin: 1.0
defaults: {iDist: 1.0, sDist: 0.01}
groups:
  arm: [panda_link3, panda_link4, panda_link5*, panda_link6, panda_link7*, panda_hand*]
pairs:
  - {name: table, robot: arm, other: table}
  - {name: person, robot: arm, other: [human_hand, human_forearm, human_upper_arm]}
  - {name: self, robot: [panda_link5*, panda_link6, panda_link7*, panda_hand*], other: [panda_link0, panda_link1, panda_link2, panda_link3]}
)",
                              "wide.yaml");
}

}  // namespace handover::control::testing
