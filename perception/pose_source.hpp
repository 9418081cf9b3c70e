// Where pose samples of the person come from: the simulated sensor, a CSV
// replay or a live UDP stream. Sources deliver samples in arrival order; the
// PerceptionEstimator keeps the latest. Perception writes estimates, never
// commands.
#pragma once

#include "perception/pose_sample.hpp"

namespace handover::perception {

class PoseSource {
 public:
  virtual ~PoseSource() = default;
  /// Next sample that has arrived by time `now` (s, controller clock) into
  /// `out`; false when none is pending. Call until false each cycle.
  /// Real-time safety is stated by each source.
  virtual bool poll(double now, PoseSample& out) = 0;
};

}  // namespace handover::perception
