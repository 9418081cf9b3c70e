// Whether a sensed body rests: measured on its displacement over a window,
// not on its speed. The velocity a filter estimates from a noisy pose
// sensor at rest stays above a few cm/s (seed 1: 3.9 mm of noise at 30 Hz
// left 0.04 m/s per axis), so a person holding still was never seen to rest;
// the filtered position's noise averages out over the window instead.
// Units: m, s, m/s. Real-time safe.
#pragma once

#include "fsm/handover/controller_interface.hpp"

namespace handover::fsm {

struct RestWindow {
  double since = -1.0;               ///< s, when the current rest began (-1: none)
  Vector3 anchor = Vector3::Zero();  ///< m, world: where it began

  void reset() { since = -1.0; }

  /// Feeds the body's position `p` at `time`. A rest begins again wherever
  /// the body has moved more than speed * window from where it began; true
  /// once it has lasted `window` (the body moved less than that over it).
  bool rests(const Vector3& p, double time, double speed, double window) {
    if (since < 0.0 || (p - anchor).norm() > speed * window) {
      since = time;
      anchor = p;
    }
    return time - since >= window;
  }
};

}  // namespace handover::fsm
