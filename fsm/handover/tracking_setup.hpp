// Puts the controller in "follow the person" mode: observation on the object
// (or hand) and tracking of the grasp frame (or presentation frame). RT safe.
#pragma once

#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// TCP pose in the hand frame that puts the object at params.object_in_hand.
inline Isometry presentationOffset(const HandoverContext& ctx) {
  return ctx.params->object_in_hand * ctx.object.grasp_in_object;
}

/// `standoff` (m) backs the tracked frame off along its own z axis (the
/// gripper's approach axis): the gripper first lines up at a pre-grasp pose
/// and then slides in along its fingers, instead of sweeping its fingertips
/// over the object or the hand while it still turns.
inline void trackTarget(HandoverContext& ctx, ControllerHandle& ctrl, bool hand, double standoff = 0.0) {
  ctrl.setObservationTarget(hand ? ObservationTarget::kHand : ObservationTarget::kObject);
  const Isometry target = hand ? presentationOffset(ctx) : ctx.object.grasp_in_object;
  ctrl.setTrackingOffset(target * Eigen::Translation3d(0.0, 0.0, -standoff));
  ctrl.clearPoseTarget();
  const HandoverParams& p = *ctx.params;
  if (p.tracking_translation_stiffness > 0.0 && p.tracking_orientation_stiffness > 0.0) {
    ctrl.setTrackingStiffness(p.tracking_translation_stiffness, p.tracking_orientation_stiffness);
  }
  ctrl.enableTracking(true);
}

}  // namespace handover::fsm
