// The give's descent onto the palm: the object goes into the receiver's hand
// from above, never up through it.
//
// Brought straight from the ready pose to a presentation above a raised hand,
// the gripper came from below and stopped under the person's hand, held there
// by the gripper-hand collision rows while its target lay above the hand (a
// local controller cannot go around): side presentations of a ball on the
// palm stalled 11 cm short until the approach timed out. So the target is
// shifted onto a surface over the presentation: a 45-degree cone standing on
// it, capped at `max_lift` (height over the presentation = the distance
// across the hand's vertical, at most max_lift). While the TCP is lower than
// the presentation (by more than 2 cm: beside or under the hand), the target
// is the surface's point straight above the TCP: the gripper rises first,
// with nothing pulling it across under the hand. Otherwise the target is the
// surface's point on the hand's vertical: the gripper comes over and descends
// along the cone as it closes in, with no stop at a pre-pose. (Rising only
// to the cone's surface switched back and forth at every centimetre the
// tracking sagged below it, and the gripper crept.) The shift changes at most `speed`
// m/s (it follows the TCP and the hand, both as noisy as their estimates).
//
// Frames: world poses; the observed frame is the receiver's hand (z its
// vertical). Units: m, m/s. Real-time safe.
#pragma once

#include <algorithm>
#include <cmath>

#include "fsm/handover/tracking_setup.hpp"

namespace handover::fsm {

/// The shift (m, hand frame) the descent asks for now; `rising`: the TCP is
/// below the presentation, the target stands above it.
inline Vector3 descentShift(const HandoverContext& ctx, double max_lift, bool* rising = nullptr) {
  // the chosen presentation on the observed hand (a turn about the hand's
  // vertical, which the controller may add, keeps one centred over the palm)
  const Isometry& hand = ctx.in.observed_pose;
  const Vector3 target = hand * ctx.presentation.offset.translation();
  const Vector3 d = hand.linear().transpose() * (ctx.in.tcp_pose.translation() - target);
  const double across = std::hypot(d.x(), d.y());
  const double surface = std::min(across, max_lift);
  // below the presentation by more than the tracking sags: rise where it is;
  // otherwise over the palm and down the cone
  const bool below = d.z() < -0.02;
  if (rising) *rising = below;
  return below ? Vector3(d.x(), d.y(), surface) : Vector3(0.0, 0.0, surface);
}

/// Moves the tracked presentation's shift toward descentShift: its height and,
/// once the TCP is no longer below the presentation, its way back over the
/// palm by at most speed * dt (dt: s since the last call); while rising the
/// target stays above the TCP however fast the hand moves. RT safe.
inline void followDescent(HandoverContext& ctx, ControllerHandle& ctrl, double max_lift, double speed, double dt) {
  const Vector3 now = ctx.tracking_shift;
  bool below = false;
  const Vector3 want = descentShift(ctx, max_lift, &below);
  const Vector3 change = below ? Vector3(0.0, 0.0, want.z() - now.z()) : Vector3(want - now);
  const double step = speed * std::max(0.0, dt);
  Vector3 next = change.norm() > step ? Vector3(now + change * (step / change.norm())) : Vector3(now + change);
  if (below) next.head<2>() = want.head<2>();
  if (next != now) setStandoff(ctx, ctrl, true, ctx.tracking_standoff, next);
}

/// Present, near the presentation: the descent's shift goes to zero by at
/// most speed * dt (over the palm, the cone held a gripper blocked a few cm
/// across as high above the presentation as it was across, out of Present's
/// tolerance; the approach's descent has done its part). RT safe.
inline void settleDescent(HandoverContext& ctx, ControllerHandle& ctrl, double speed, double dt) {
  const Vector3 now = ctx.tracking_shift;
  if (now.isZero()) return;
  const double step = speed * std::max(0.0, dt);
  const Vector3 next = now.norm() > step ? Vector3(now * (1.0 - step / now.norm())) : Vector3::Zero();
  setStandoff(ctx, ctrl, true, ctx.tracking_standoff, next);
}

}  // namespace handover::fsm
