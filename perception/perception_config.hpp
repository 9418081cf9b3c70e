// Estimator settings from config/perception.yaml, strictly validated.
// Start-up only (allocates, throws).
#pragma once

#include <string>

#include "config/yaml_reader.hpp"
#include "perception/perception_estimator.hpp"
#include "perception/reach_predictor.hpp"

namespace handover::perception {

struct PerceptionConfig {
  /// The estimator: staleness, motion model, prediction, gates (the object's
  /// place in the hand stays identity: the scenario sets it).
  EstimatorSettings estimator = defaults();
  double blend_time = 0.5;  ///< s, observation-target switch blend
  ReachPredictorSettings reach;  ///< where a reaching hand will come to rest

  /// The product's defaults (as config/perception.yaml ships them).
  static EstimatorSettings defaults();
};

/// Reads a perception config; unknown keys, wrong types and out-of-range
/// values throw InputError naming the file, key and line.
PerceptionConfig loadPerceptionConfig(const std::string& path);
PerceptionConfig parsePerceptionConfig(const YamlReader& root);
/// HANDOVER_SOURCE_DIR/config/perception.yaml
std::string defaultPerceptionConfigPath();

}  // namespace handover::perception
