// BackOut: after the fingers let go of an object the person keeps, withdraw
// the way they came in - straight back along the approach axis (TCP -z), at
// the current orientation - before turning toward the stow pose. Going
// straight to the stow pose turns the gripper while its fingers still
// straddle the object: they strike it and spin the wrist (joint 7 past its
// velocity limit) or drag it from the person's hand.
//
// While the fingers still straddle it, the person may pull the object into
// a finger or the palm (a box taken away along the axis the fingers close
// along): they do not yield, and an arm that holds its place against them is
// dragged after the object, its wrist past its velocity limit when it comes
// free. The goal yields instead: it moves along what pushes the open gripper
// across the approach axis beyond `yield_force` (HandoverInput::tool_contact),
// at `yield_rate` per newton above it, at most `yield_distance` in all, so the
// finger rides along with the object, lightly, while the gripper backs off it.
//
// A force only tells once the finger is struck, so the goal also rides along
// with the object as it is seen leaving (ReleaseRide),
// and it backs out on a minimum-jerk profile over `duration`, its rate fed
// forward: a set-point step at the pose task's gains crept back 1.5 cm in the
// first 0.18 s while the receiver took the object into a finger.
//
// A take given up while the fingers are around the object the person keeps
// (they take it back as the fingers close, or never let go) is the same
// exchange the other way round: `open_gripper` opens them as it starts. A
// person who withdraws pulls the object across the approach axis; a gripper
// sent straight to its retreat pose held the fingers on it and was dragged
// after it, the wrist spun past its velocity limit (g1013_00380). There the
// object may be clear of the fingers already (withdrawn before they reached
// it) or soon: `until_object_clear` ends the back-out once the object is
// seen clear of them (its shape outside the fingers' reach), instead of a
// gripper that backs out of nothing for a second while the arm's approach
// momentum carries it on.
#pragma once

#include "fsm/handover/handover_state.hpp"
#include "fsm/handover/release_ride.hpp"

namespace handover::fsm {

/// [Clear] Tracking off, observation none; pose task to the TCP pose
/// `distance` behind the current one along its z axis, reached on a
/// minimum-jerk profile over `duration`; moved along the contact force across
/// that axis while it exceeds yield_force, and along with the object leaving
/// (ReleaseRide). Clear once the TCP has moved back along that axis to within
/// position_tolerance of `distance`. Keys: distance (m), duration (s), position_tolerance
/// (m), yield_force (N), yield_rate (m/s per N), yield_distance (m),
/// open_gripper (bool, default false: the fingers let go as it starts),
/// until_object_clear (bool, default false: Clear also once the object is
/// seen clear of the fingers, objectClear()); `timeout`
/// (s) gives output Timeout (the transition table decides; usually the same as
/// Clear). Real-time safe.
class BackOut : public HandoverState {
 public:
  BackOut();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  int clear_;
  double distance_ = 0.08, duration_ = 0.3, pos_tol_ = 0.01;
  double start_time_ = 0.0;
  double yield_force_ = 20.0, yield_rate_ = 0.01, yield_distance_ = 0.15;  // config/fsm.yaml sets them
  bool open_gripper_ = false;
  bool until_object_clear_ = false;
  /// The object seen (fresh) with its shape clear of the fingers' reach: the
  /// approach axis from `distance` behind the TCP to the pad tips, grown by
  /// half the open width and a pad's half span. False when unseen or its shape
  /// is unknown. RT safe.
  bool objectClear(const HandoverContext& ctx) const;
  Isometry start_ = Isometry::Identity();  ///< the TCP when the fingers let go
  Vector3 yielded_ = Vector3::Zero();      ///< m, how far the goal moved along the contact force
  double last_time_ = 0.0;
  ReleaseRide ride_;
};

}  // namespace handover::fsm
