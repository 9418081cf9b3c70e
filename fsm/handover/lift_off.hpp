// The lift-off after a take: the object leaves the person's hand the way the
// gripper came in, never lower, before the carry lowers it toward the stow
// pose. The carry's joint-space move starts with its full pull toward the
// goal, so a stow lower than the grasp dropped the object at once (20-30 cm
// in the second after the person let go), and a higher one could still dip
// it on the straight line in joint space (up to 14 cm): 192 of seed 1's 423
// releases sank more than 1 cm. To the person it looks as if the arm gave way
// under the weight it had just taken, and it sweeps the object down past
// their fingers. A receiver draws the object back and up first.
// RT safe: no allocation.
#pragma once

#include <algorithm>
#include <cmath>

#include "control/types.hpp"

namespace handover::fsm {

/// The way out of a grasp for a TCP at `tcp` (world frame): back along the
/// approach axis (TCP -z) without its downward part, raised to at least
/// `min_elevation` (rad) above the horizontal so the object also comes up off
/// the palm. A gripper that came up from below (nothing left of the axis)
/// draws back toward the robot's base (world origin). Unit vector, world frame.
inline Vector3 liftOffDirection(const Isometry& tcp, double min_elevation) {
  const Vector3 back = -tcp.linear().col(2);
  Vector3 horizontal(back.x(), back.y(), 0.0);
  double up = std::max(back.z(), 0.0);
  if (horizontal.norm() < 1e-3 && up < 1e-3) horizontal = Vector3(-tcp.translation().x(), -tcp.translation().y(), 0.0);
  if (horizontal.norm() < 1e-9) return Vector3::UnitZ();  // straight above the base, or straight up already
  up = std::max(up, horizontal.norm() * std::tan(min_elevation));
  return Vector3(horizontal.x(), horizontal.y(), up).normalized();
}

}  // namespace handover::fsm
