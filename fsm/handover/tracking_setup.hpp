// Puts the controller in "follow the person" mode: observation on the object
// (or hand) and tracking of the grasp frame (or presentation frame). RT safe.
#pragma once

#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// TCP pose in the hand frame that puts the object at params.object_in_hand.
inline Isometry presentationOffset(const HandoverContext& ctx) {
  return ctx.params->object_in_hand * ctx.object.grasp_in_object;
}

inline void trackTarget(HandoverContext& ctx, ControllerHandle& ctrl, bool hand) {
  ctrl.setObservationTarget(hand ? ObservationTarget::kHand : ObservationTarget::kObject);
  ctrl.setTrackingOffset(hand ? presentationOffset(ctx) : ctx.object.grasp_in_object);
  ctrl.clearPoseTarget();
  ctrl.enableTracking(true);
}

}  // namespace handover::fsm
