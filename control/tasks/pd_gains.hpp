// Stiffness/damping pair of a PD task: mu = -stiffness e - damping edot.
#pragma once

#include <cmath>

namespace handover::control {

struct PdGains {
  double stiffness = 1.0;  ///< 1/s^2
  double damping = 2.0;    ///< 1/s

  /// Critically damped gains: damping = 2 sqrt(stiffness).
  static PdGains critical(double stiffness) { return PdGains{stiffness, 2.0 * std::sqrt(stiffness)}; }
};

}  // namespace handover::control
