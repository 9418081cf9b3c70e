// Integrates the virtual observed object's state from the solved
// alphadot_obs each cycle (paper II-B: s_obs). Position and linear velocity
// are integrated exactly for a constant acceleration over the step; the
// orientation by the exponential map of the mean angular velocity (world
// axes, left multiplication). Real-time safe.
#pragma once

#include "control/formulation/control_context.hpp"

namespace handover::control {

class ObservedObjectIntegrator {
 public:
  /// Places the observed object at `pose` with velocity `velocity` ([m/s; rad/s], world).
  void reset(const Isometry& pose, const Vector6& velocity = Vector6::Zero());
  /// Advances by dt (s) with acceleration [linear (m/s^2); angular (rad/s^2)], world axes.
  /// Non-finite input is ignored (the state keeps its last velocity at zero
  /// acceleration), so a failed solve never corrupts the state.
  void integrate(const Vector6& acceleration, double dt);
  const ObservedState& state() const { return state_; }

 private:
  ObservedState state_;
};

}  // namespace handover::control
