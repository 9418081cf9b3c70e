// Settings of the simulated wearable pose sensor (scenario `sensor:` section,
// design notes 2). Plain data; validated by the scenario parser.
#pragma once

#include <Eigen/Geometry>
#include <utility>
#include <vector>

namespace handover::perception {

struct SensorSettings {
  double rate_hz = 60.0;       ///< samples per second (> 0)
  double latency = 0.0;        ///< s from measurement to delivery (>= 0)
  double noise_pos = 0.0;      ///< m, standard deviation per axis and sample
  double noise_rot_deg = 0.0;  ///< deg, standard deviation of each rotation-vector component
  /// [begin, end) intervals, s, ordered and disjoint: no sample is measured inside them.
  std::vector<std::pair<double, double>> dropouts;
  /// Constant calibration error: position added in world axes, rotation
  /// applied in each body's own frame (measured R = R_true * R_offset).
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
};

}  // namespace handover::perception
