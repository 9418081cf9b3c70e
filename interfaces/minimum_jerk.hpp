// Minimum-jerk profile (Flash and Hogan 1985): the phase of a rest-to-rest
// motion, x(t) = x0 + (x1 - x0) * minimumJerkPhase(t / T).
// Dimensionless; real-time safe. One definition for the simulated person's
// reaches, the reach predictor's fit, the observation target's blend and
// the state machine's own timed moves.
#pragma once

#include <algorithm>

namespace handover {

/// Phase in [0, 1] at normalised time s (clamped to [0, 1]): 10s^3 - 15s^4 + 6s^5.
inline double minimumJerkPhase(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * s * (10.0 + s * (-15.0 + 6.0 * s));
}

/// d(phase)/ds at s (0 outside [0, 1]); peak 1.875 at s = 0.5.
inline double minimumJerkRate(double s) {
  if (s <= 0.0 || s >= 1.0) return 0.0;
  return 30.0 * s * s * (1.0 - s) * (1.0 - s);
}

/// d2(phase)/ds2 at s (0 outside [0, 1]); extremes +-5.7735 at s = 0.5 -+ 0.2887.
inline double minimumJerkAccel(double s) {
  if (s <= 0.0 || s >= 1.0) return 0.0;
  return 60.0 * s * (1.0 - s) * (1.0 - 2.0 * s);
}

}  // namespace handover
