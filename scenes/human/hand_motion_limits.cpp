#include "scenes/human/hand_motion_limits.hpp"

#include <algorithm>
#include <cmath>

namespace handover::human {

double plausibleDuration(double written, double distance, double angle, const HandMotionLimits& limits) {
  // minimum jerk: peak speed 1.875 D / T, peak acceleration 5.7735 D / T^2
  double t = written;
  if (limits.max_speed > 0.0) t = std::max(t, 1.875 * distance / limits.max_speed);
  if (limits.max_acceleration > 0.0) t = std::max(t, std::sqrt(5.7735 * distance / limits.max_acceleration));
  if (limits.max_angular_speed > 0.0) t = std::max(t, 1.875 * angle / limits.max_angular_speed);
  return t;
}

}  // namespace handover::human
