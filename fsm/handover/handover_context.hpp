// The context the handover states see: this cycle's inputs, the shared
// parameters, the controller ledger, the counters and a few values derived
// once per cycle by HandoverFsm::step (the filtered force).
#pragma once

#include "fsm/core/context.hpp"
#include "fsm/handover/carry_request.hpp"
#include "fsm/handover/controller_handle.hpp"
#include "fsm/handover/handover_io.hpp"
#include "fsm/handover/handover_params.hpp"

namespace handover::fsm {

/// A tracking target a state committed to: the planner's choice when it had
/// one, else the declared one (the controller then resolves the free axis).
struct TrackedChoice {
  Isometry offset = Isometry::Identity();  ///< target frame in the observed frame
  bool planned = false;
  int index = -1;                           ///< the plan's candidate (-1: declared)
  Vector7 q_target = Vector7::Zero();       ///< rad, posture reference at the target (planned only)
  Vector7 q_pre = Vector7::Zero();          ///< rad, posture reference at the pre-target (planned only)

  /// Takes `plan` when it is valid and a different candidate; true if it changed.
  bool adopt(const TrackingPlan& plan) {
    if (!plan.valid || (planned && plan.index == index)) return false;
    offset = plan.target_in_observed;
    planned = true;
    index = plan.index;
    q_target = plan.q_target;
    q_pre = plan.q_pre;
    return true;
  }
};

struct HandoverContext : Context {
  HandoverInput in;                    ///< this cycle's inputs (sanitised)
  ObjectInfo object;                   ///< what the task knows about the object
  const HandoverParams* params = nullptr;
  CommandLedger* ledger = nullptr;
  HandoverStats stats;
  /// Retreat gave the person another attempt; counted (stats.retries) once
  /// they come back, so a person who left for good made no retry.
  bool retry_pending = false;
  PlannerInterface* planner = nullptr;  ///< optional (null: declared grasps and named poses only)
  /// Upright placements the states ask for; answered outside the step (HandoverFsm::plan).
  CarryChannel carry;

  /// The grasp on the object the take tracks and, once closed, holds
  /// (grasp frame in the object frame); starts as the declared grasp.
  TrackedChoice grasp;
  /// The give's TCP in the receiver's hand frame; starts as the declared
  /// presentation (params.object_in_hand with the declared grasp).
  TrackedChoice presentation;
  /// m: how far the tracked target is backed off along its approach axis, as
  /// trackTarget (tracking_setup.hpp) last commanded it.
  double tracking_standoff = 0.0;
  /// m/s: how fast that standoff changes, as last commanded (a funnel's slide;
  /// 0 for a standoff set once).
  double tracking_standoff_rate = 0.0;
  /// m, observed frame: how far the tracked target is shifted from the
  /// chosen one (a give: raised over the receiver's hand, and beside it while
  /// the gripper rises: presentation_descent.hpp), as setStandoff last
  /// commanded it.
  Vector3 tracking_shift = Vector3::Zero();

  /// The object's pose in the TCP frame, held with `grasp`.
  Isometry objectInTcp() const { return grasp.offset.inverse(); }
  /// Centre of mass of the object in the TCP frame, held with `grasp`, m.
  Vector3 comInTcp() const { return objectInTcp() * (object.grasp_in_object * object.com_in_tcp); }

  Vector3 force = Vector3::Zero();               ///< low-pass filtered F/T force, world axes, N
  bool force_valid = false;                      ///< at least one finite sample filtered
  Vector3 force_before_grasp = Vector3::Zero();  ///< filtered force when the fingers started closing (h2r)
  Vector3 force_holding = Vector3::Zero();       ///< filtered force while presenting the object (r2h)
  /// HandoverInput::interaction_force (filtered by the estimator, not again here), N, world
  Vector3 interaction = Vector3::Zero();
  Vector3 interaction_holding = Vector3::Zero();  ///< `interaction` as presenting started (r2h pull tests)

  /// Where the person's hand and the object were first seen (m, world): the
  /// place the hand rests before it reaches and returns to when the person
  /// gives up (set once, by HandoverFsm::step, from the first valid sample).
  Vector3 home_hand = Vector3::Zero(), home_object = Vector3::Zero();
  bool home_hand_known = false, home_object_known = false;
  /// Each one's distance (m) from its home, low-passed by params.away_time_constant, and the
  /// farthest that has been since (HandoverFsm::step): back home after it went out is a person
  /// back at rest, not one who waits there
  double hand_from_home = 0.0, object_from_home = 0.0;
  double hand_farthest_from_home = 0.0, object_farthest_from_home = 0.0;
  /// The object changed hands (a take's release, a give's object confirmed
  /// gone): all that is left is to stow; a restart after a safety stop must
  /// not choose a direction from what the gripper holds (it offered a taken
  /// object back to the person)
  bool exchanged = false;

  /// Weight (N) added to the sensor since `baseline`, along gravity.
  double addedWeight(const Vector3& baseline) const {
    return (force.z() - baseline.z()) * params->ft_gravity_sign;
  }
};

}  // namespace handover::fsm
