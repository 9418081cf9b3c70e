// `batch --vary N`: randomized variants of a scenario with reproducible
// seeds. A variant moves the handover location, turns the object, changes
// the person's timing and the sensor noise, then is checked like a file
// (a variant the person cannot reach is drawn again).
#pragma once

#include <cstdint>

#include "scenes/scenario/scenario.hpp"

namespace handover::app {

struct VariationRanges {
  Eigen::Vector3d location{0.08, 0.10, 0.06};  ///< m, +- shift of every reach/withdraw/pull target (x, y, z)
  double object_yaw = 0.5;       ///< rad, +- turn of the object in the hand (about the hand z)
  double target_yaw = 0.4;       ///< rad, +- turn of the reach targets' yaw
  double timing = 0.25;          ///< reach/hold durations scaled by 1 +- this
  double noise_min = 0.5;        ///< sensor noise scaled by a factor in [noise_min, noise_max]
  double noise_max = 2.0;
  int max_draws = 20;            ///< draws before giving up on an unreachable variant
};

/// Seed of variant `k` of a scenario whose own seed is `base` (k >= 1).
std::uint64_t variantSeed(int base, int k);

/// Variant `k` (k >= 1) of `base`, named "<name>#k". Throws InputError if no
/// valid variant was found within max_draws.
scenario::Scenario makeVariant(const scenario::Scenario& base, int k, const VariationRanges& ranges = {});

}  // namespace handover::app
