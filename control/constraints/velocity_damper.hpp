// The velocity damper (mc_rtc style) shared by the limit constraints: a
// scalar x that must stay away from a limit, d = its distance to the limit
// (growing away from it), x_dot = d's rate. Inside the interaction distance di
// the rate toward the limit is bounded by
//   x_dot >= -xi (d - ds) / (di - ds),
// xi chosen when x enters the zone so the bound starts at the current rate
// (plus offset * (di - ds) per second of slack) and kept until it leaves;
// below ds the bound turns positive (leave, at most `recovery` per second).
// Over one period dt this is a lower bound on x_ddot; a second bound keeps
// the constant-acceleration prediction at least ds/2 from the limit.
// Header-only, real-time safe.
#pragma once

#include <algorithm>
#include <limits>

namespace handover::control {

/// Lower bound on x_ddot (-inf while d >= di). `xi` is the damper's state
/// (0 = off), updated here.
inline double velocityDamperBound(double d, double x_dot, double di, double ds, double offset, double recovery,
                                  double dt, double& xi) {
  if (d >= di) {
    xi = 0.0;
    return -std::numeric_limits<double>::infinity();
  }
  const double span = di - ds;
  if (xi <= 0.0) {
    // entering: start the bound at the current approach rate, plus slack
    const double approach = std::max(0.0, -x_dot);
    const double gap = std::max(d - ds, 1e-9);
    xi = approach * span / gap + offset * span;
    xi = std::max(xi, 1e-9);
  }
  double v_min = -xi * (d - ds) / span;  // > 0 inside the safety zone: move out
  v_min = std::min(v_min, recovery);
  const double damper = (v_min - x_dot) / dt;
  // never predict beyond ds/2 from the limit over the next step
  const double position = 2.0 * (0.5 * ds - d - x_dot * dt) / (dt * dt);
  return std::max(damper, position);
}

}  // namespace handover::control
