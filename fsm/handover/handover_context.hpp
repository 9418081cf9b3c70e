// The context the handover states see: this cycle's inputs, the shared
// parameters, the controller ledger, the counters and a few values derived
// once per cycle by HandoverFsm::step (the filtered force).
#pragma once

#include "fsm/core/context.hpp"
#include "fsm/handover/controller_handle.hpp"
#include "fsm/handover/handover_io.hpp"
#include "fsm/handover/handover_params.hpp"

namespace handover::fsm {

struct HandoverContext : Context {
  HandoverInput in;                    ///< this cycle's inputs (sanitised)
  ObjectInfo object;                   ///< what the task knows about the object
  const HandoverParams* params = nullptr;
  CommandLedger* ledger = nullptr;
  HandoverStats stats;

  Vector3 force = Vector3::Zero();               ///< low-pass filtered F/T force, world axes, N
  bool force_valid = false;                      ///< at least one finite sample filtered
  Vector3 force_before_grasp = Vector3::Zero();  ///< filtered force when the fingers started closing (h2r)
  Vector3 force_holding = Vector3::Zero();       ///< filtered force while presenting the object (r2h)

  /// Weight (N) added to the sensor since `baseline`, along gravity.
  double addedWeight(const Vector3& baseline) const {
    return (force.z() - baseline.z()) * params->ft_gravity_sign;
  }
};

}  // namespace handover::fsm
