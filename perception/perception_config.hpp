// Estimator settings from config/perception.yaml, strictly validated.
// Start-up only (allocates, throws).
#pragma once

#include <string>

#include "config/yaml_reader.hpp"

namespace handover::perception {

struct PerceptionConfig {
  double max_gap = 0.1;          ///< s without a new sample: the stream stopped (stale)
  double max_latency = 0.2;      ///< s, a sample older than this on arrival is too late to act on
  double smoothing_time = 0.03;  ///< s, estimator smoothing time constant for positions (0 = none)
  double rotation_smoothing_time = 0.1;  ///< s, the same for rotations (0 = none)
  double blend_time = 0.5;       ///< s, observation-target switch blend
};

/// Reads a perception config; unknown keys, wrong types and out-of-range
/// values throw InputError naming the file, key and line.
PerceptionConfig loadPerceptionConfig(const std::string& path);
PerceptionConfig parsePerceptionConfig(const YamlReader& root);
/// HANDOVER_SOURCE_DIR/config/perception.yaml
std::string defaultPerceptionConfigPath();

}  // namespace handover::perception
