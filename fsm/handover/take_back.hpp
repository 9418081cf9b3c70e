// A person taking back the object they share with the robot: the pull felt
// and seen (pulledBack, perception_checks.hpp) lasting long enough to be
// more than a jolt. Used while the fingers close on the object (Grasp) and
// while they hold it before the release (WaitForRelease). RT safe.
#pragma once

#include "fsm/handover/handover_context.hpp"
#include "fsm/handover/perception_checks.hpp"

namespace handover::fsm {

/// A person taking back the object the fingers close on or hold while they
/// still carry it: pulledBack (perception_checks.hpp) with
/// params.take_back_force, for a while. RT safe.
class TakeBack {
 public:
  void restart() { since_ = -1.0; }
  /// True once the pull has lasted `hold` s (never with take_back_force 0).
  /// `hand_speed` (m/s): how fast the hand must go (pulledBack).
  bool pulled(const HandoverContext& ctx, double hold, double hand_speed = 0.0) {
    const double f = ctx.params->take_back_force;
    return lasted(ctx, hold, f > 0.0 && pulledBack(ctx, f, hand_speed));
  }
  /// True once the object has carried the open fingers along the hand's way
  /// (carriedThrough with take_back_force; `significance`: standard
  /// deviations of the hand's speed that are noise) for `hold` s; with
  /// `home_only`, only while the hand goes back toward where it was first
  /// seen (goingHome: a person who moves the object the fingers hold
  /// elsewhere is not taking it back).
  bool carried(const HandoverContext& ctx, double hold, double significance, bool home_only = false) {
    const double f = ctx.params->take_back_force;
    return lasted(ctx, hold, f > 0.0 && carriedThrough(ctx, f, significance) && (!home_only || goingHome(ctx)));
  }

 private:
  bool lasted(const HandoverContext& ctx, double hold, bool now) {
    if (!now) {
      since_ = -1.0;
      return false;
    }
    if (since_ < 0.0) since_ = ctx.time;
    return ctx.time - since_ >= hold;
  }
  double since_ = -1.0;  ///< s, the pull began (< 0: none)
};

}  // namespace handover::fsm
