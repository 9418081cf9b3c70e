// Shared helpers of the grasp tests: the Panda model from scenes/panda.urdf
// and random configurations inside its limits.
#pragma once

#include <random>
#include <string>

#include "control/grasp/chain_kinematics.hpp"
#include "control/grasp/grasp_selection_config.hpp"
#include "control/model/model.hpp"
#include "tests/support/panda_model.hpp"

namespace handover::control::grasp::testing {

using handover::test::panda;

/// Uniform in [q_min + inset, q_max - inset] (rad).
inline Vector7 randomConfiguration(const Model& model, std::mt19937& rng, double inset = 0.0) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vector7 q;
  for (int i = 0; i < kArmDofs; ++i) {
    const double lo = model.q_min[i] + inset, hi = model.q_max[i] - inset;
    q[i] = lo + u(rng) * (hi - lo);
  }
  return q;
}

/// The TCP pose at q (world), through the IK's own chain kinematics.
inline Isometry tcpPose(const Model& model, const Vector7& q) {
  ChainPoses poses;
  chainPoses(model, q, poses);
  return chainFramePose(model, poses, model.frameId("tcp"));
}

/// The "ready" pose of the facts sheet (rad).
inline Vector7 readyConfiguration() {
  Vector7 q;
  q << 0.0, -0.785398, 0.0, -2.356194, 0.0, 1.570796, 0.785398;
  return q;
}

/// The shipped config/grasp_selection.yaml.
inline const GraspSelectionConfig& shippedConfig() {
  static const GraspSelectionConfig config =
      loadGraspSelectionConfig(std::string(HANDOVER_SOURCE_DIR) + "/config/grasp_selection.yaml");
  return config;
}

}  // namespace handover::control::grasp::testing
