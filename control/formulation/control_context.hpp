// What tasks and constraints read each cycle. Everything here is computed
// once per cycle (model quantities by computeAll, the observed object by the
// observation integrator) and then only read.
#pragma once

#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"
#include "control/types.hpp"

namespace handover::control {

/// Variable layout of the QP, owned by the formulation:
/// chi = [qddot (7) ; alphadot_obs (6) = [linear accel; angular accel] of the observed frame].
struct VariableLayout {
  static constexpr int kQdd = 0;   ///< first index of qddot
  static constexpr int kObs = kArmDofs;  ///< first index of the observed object's acceleration
  static constexpr int kSize = kNumVars;
};

/// State of the virtual floating "observed object" (paper II-B), world axes.
struct ObservedState {
  Isometry pose = Isometry::Identity();  ///< X_obs
  Vector6 velocity = Vector6::Zero();    ///< alpha_obs = [Pdot; omega]
  Vector6 acceleration = Vector6::Zero();///< alphadot_obs of the last solved cycle
};

struct ControlContext {
  const Model* model = nullptr;
  const Data* data = nullptr;       ///< computeAll() already run for (q, v)
  double time = 0.0;                ///< s
  double dt = 0.001;                ///< control period, s
  ObservedState observed;           ///< observed object state at the start of the cycle
  /// J_c^T f of the known external wrench f on the robot (Controller::
  /// setExternalWrench), N m: the dynamics are M qddot + h = tau + tau_external.
  Vector7 tau_external = Vector7::Zero();
};

}  // namespace handover::control
