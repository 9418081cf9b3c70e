// Puts the controller in "follow the person" mode: observation on the object
// (or hand) and tracking of the grasp frame (or presentation frame). RT safe.
#pragma once

#include <algorithm>

#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// The target a state tracks on the object (take) or on the hand (give).
inline TrackedChoice& trackedChoice(HandoverContext& ctx, bool hand) { return hand ? ctx.presentation : ctx.grasp; }

/// The planner's latest choice for the object (take) or the hand (give).
inline const TrackingPlan& latestPlan(const HandoverContext& ctx, bool hand) {
  return hand ? ctx.in.hand_plan : ctx.in.object_plan;
}

/// `standoff` (m) backs the tracked frame off along its own z axis (the
/// gripper's approach axis): the gripper first lines up at a pre-grasp pose
/// and then slides in along its fingers, instead of sweeping its fingertips
/// over the object or the hand while it still turns.
/// A planned target is tracked exactly, and the posture task's reference
/// becomes its IK configuration (pre-target while backed off), so the QP's
/// local motion leads to a configuration known to reach it instead of into
/// a joint limit (redundancy resolution).
/// Which phase gains track it (params.tracking): following the person, or
/// lining the fingers up on the object in the person's hand (Grasp).
enum class TrackingGains { kFollow, kAlign };

/// Sets the tracking task's phase gains. RT safe.
inline void setTrackingGains(const HandoverParams& p, ControllerHandle& ctrl, TrackingGains gains) {
  if (gains == TrackingGains::kAlign && p.align_tracking_translation_stiffness > 0.0 &&
      p.align_tracking_orientation_stiffness > 0.0) {
    ctrl.setTrackingStiffness(p.align_tracking_translation_stiffness, p.align_tracking_orientation_stiffness,
                              p.align_tracking_max_speed);
  } else if (p.tracking_translation_stiffness > 0.0 && p.tracking_orientation_stiffness > 0.0) {
    ctrl.setTrackingStiffness(p.tracking_translation_stiffness, p.tracking_orientation_stiffness);
  }
}

/// A set-point held against the person (the fingers on the object, a
/// presentation waiting for the pull) at the tracking's closing gains: the
/// pose task's own K = 6, meant for retracts, is a weak spring at the wrist
/// (K M_77, about 0.1 N m/rad), and the arm gives way to what it holds and
/// to the person. RT safe.
inline void holdAtClosingGains(const HandoverParams& p, ControllerHandle& ctrl) {
  ctrl.setPoseStiffness(p.closing_tracking_translation_stiffness, p.closing_tracking_orientation_stiffness);
}

/// The phase gains for a tracked body moving at `speed` (m/s): at rest the
/// phase's own stiff gains (kFollow: params.arrive_tracking_*, or in a `take`
/// params.take_arrive_tracking_* where set; kAlign: params.align_tracking_*),
/// the follow gains from the arrive speed on, linear between: soft while the
/// person still brings the body in, stiff once it has arrived. Without
/// arrive gains, the phase gains as they are. RT safe.
inline void setPhaseGainsForSpeed(const HandoverParams& p, ControllerHandle& ctrl, TrackingGains phase, double speed,
                                  bool take = false) {
  const bool align = phase == TrackingGains::kAlign && p.align_tracking_translation_stiffness > 0.0 &&
                     p.align_tracking_orientation_stiffness > 0.0;
  const bool take_own = !align && take && p.take_arrive_tracking_translation_stiffness > 0.0 &&
                        p.take_arrive_tracking_orientation_stiffness > 0.0;
  const double rest_t = align ? p.align_tracking_translation_stiffness
                              : take_own ? p.take_arrive_tracking_translation_stiffness
                                         : p.arrive_tracking_translation_stiffness;
  const double rest_o = align ? p.align_tracking_orientation_stiffness
                              : take_own ? p.take_arrive_tracking_orientation_stiffness
                                         : p.arrive_tracking_orientation_stiffness;
  const double arrive_speed = take_own ? p.take_arrive_speed : p.arrive_speed;
  if (arrive_speed <= 0.0 || rest_t <= 0.0 || rest_o <= 0.0 || p.tracking_translation_stiffness <= 0.0 ||
      p.tracking_orientation_stiffness <= 0.0) {
    setTrackingGains(p, ctrl, phase);
    return;
  }
  const double moving = std::clamp(speed / arrive_speed, 0.0, 1.0);
  ctrl.setTrackingStiffness(rest_t + moving * (p.tracking_translation_stiffness - rest_t),
                            rest_o + moving * (p.tracking_orientation_stiffness - rest_o),
                            align ? p.align_tracking_max_speed : 0.0);
}

/// Backs the tracked target off by `standoff` (m) along its approach axis
/// and shifts it by `shift` (m, in the observed body's frame: a give's
/// descent onto the palm, presentation_descent.hpp), the posture reference
/// with it. `rate` (m/s) and `acceleration` (m/s^2): how the standoff
/// changes now (a funnel's slide), fed forward to the tracking. RT safe.
inline void setStandoff(HandoverContext& ctx, ControllerHandle& ctrl, bool hand, double standoff,
                        const Vector3& shift = Vector3::Zero(), double rate = 0.0, double acceleration = 0.0) {
  const TrackedChoice& c = trackedChoice(ctx, hand);
  const Vector7& q_plan = standoff > 0.0 ? c.q_pre : c.q_target;
  ctrl.setTrackingOffset(TrackingOffset{Eigen::Translation3d(shift) * c.offset * Eigen::Translation3d(0.0, 0.0, -standoff),
                                        c.planned, q_plan, -rate, -acceleration});
  ctx.tracking_standoff = standoff;
  ctx.tracking_standoff_rate = rate;
  ctx.tracking_shift = shift;
  if (c.planned) ctrl.setPostureTarget(q_plan);
}

inline void trackTarget(HandoverContext& ctx, ControllerHandle& ctrl, bool hand, double standoff = 0.0,
                        TrackingGains gains = TrackingGains::kFollow, const Vector3& shift = Vector3::Zero()) {
  ctrl.setObservationTarget(hand ? ObservationTarget::kHand : ObservationTarget::kObject);
  setStandoff(ctx, ctrl, hand, standoff, shift);
  ctrl.clearPoseTarget();
  setTrackingGains(*ctx.params, ctrl, gains);
  ctrl.enableTracking(true);
}

/// The tracked grasp (or presentation) frame itself, world: the target the
/// controller tracked last cycle moved forward by the standoff it was backed
/// off by and back by the shift it was shifted by (exact also when the
/// controller resolves a free axis itself).
inline Isometry trackedGraspFrame(const HandoverContext& ctx) {
  Isometry frame = ctx.in.target_pose * Eigen::Translation3d(0.0, 0.0, ctx.tracking_standoff);
  frame.translation() -= ctx.in.observed_pose.linear() * ctx.tracking_shift;
  return frame;
}

/// While a state may still change its mind (approaching): follows the
/// planner's choice when it switches. True if the target changed.
inline bool followPlan(HandoverContext& ctx, ControllerHandle& ctrl, bool hand, double standoff = 0.0) {
  if (!trackedChoice(ctx, hand).adopt(latestPlan(ctx, hand))) return false;
  trackTarget(ctx, ctrl, hand, standoff, TrackingGains::kFollow, ctx.tracking_shift);
  return true;
}

}  // namespace handover::fsm
