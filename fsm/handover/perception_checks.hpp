// Small geometric tests the handover states share. All RT safe.
#pragma once

#include <optional>

#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// Where the receiver's hand (`hand`) or the offered object was first seen
/// (HandoverContext::home_*, world, m): the person's rest place; null while
/// it has not been seen.
const Vector3* homeOf(const HandoverContext& ctx, bool hand);
/// The farthest (m) the receiver's hand (`hand`) or the offered object has
/// gone from its home, its distance low-passed by params.away_time_constant
/// (HandoverContext::*_farthest_from_home).
double farthestFromHome(const HandoverContext& ctx, bool hand);
/// m: how far the hand (or the object) is from home now, low-passed as farthestFromHome's.
double fromHome(const HandoverContext& ctx, bool hand);
/// Speed of `body` toward `center` (m/s, > 0 when approaching).
double speedToward(const Vector3& center, const SensedBody& body);
/// A usable and recent sample.
bool fresh(const SensedBody& body, double max_age);
/// The receiver's hand (`hand`) or the offered object is in the meeting
/// region (HandoverParams::workspace), at its rest pose when the approach
/// anticipates the reach. An offered object also counts while the hand that
/// holds it is there: the handover location is the person's grip point (the
/// scenario contract bounds that point by the region), and the object they
/// hold out reaches beyond it by up to its own size. `margin` (m) grows the
/// region (Workspace::contains).
bool inWorkspace(const HandoverContext& ctx, bool hand, double margin = 0.0);
/// The receiver's hand (`hand`) or the offered object moves away from the
/// workspace centre faster than withdraw_speed, or heads back (within 30
/// degrees) toward where it rested before the reach (HandoverContext::home_*)
/// that fast: a hand resting beside the meeting point goes back along the
/// robot's reach more than away from it.
bool leaving(const HandoverContext& ctx, bool hand);
/// The halves of leaving(): away from the workspace centre faster than
/// withdraw_speed; toward HandoverContext::home_* that fast, within 30 degrees.
bool movingAway(const HandoverContext& ctx, bool hand);
bool headingHome(const HandoverContext& ctx, bool hand);
/// What tells a withdrawal without the motion: true when perception has been
/// stale for longer than stale_timeout or the body is outside the workspace
/// grown by withdraw_workspace_margin (inWorkspace: a hysteresis band against
/// the sensor's noise at the region's edge); false during a short dropout
/// (keep the last decision); empty: the motion decides.
std::optional<bool> withdrawnAtOnce(const HandoverContext& ctx, bool hand);
/// The person withdrew the receiver's hand (`hand`) or the offered object,
/// judged on this sample alone: withdrawnAtOnce(), else leaving(). For the fingers closing on an object (Grasp): there any motion
/// away counts. Elsewhere WithdrawalWatch (withdrawal_watch.hpp) asks for
/// the motion to carry the body away.
bool withdrawn(const HandoverContext& ctx, bool hand);
/// The person pulls the object they share with the robot back where they
/// brought it from: the wrist feels more than `force` (N) beyond the object's
/// weight (HandoverContext::interaction) across the floor toward the place
/// their hand rested before it reached (HandoverContext::home_hand), and
/// their hand, seen now, moves that way. Across the floor: the object's
/// weight is modelled only once the robot carries it (before, it reads as a
/// lift), and a pull down and away reads as that weight. `hand_speed` (m/s):
/// how fast the hand must move that way (0: any motion that way).
bool pulledBack(const HandoverContext& ctx, double force, double hand_speed = 0.0);

/// The object the person carries off through the open fingers: what
/// touches the gripper (HandoverContext::interaction, the whole load while
/// it holds nothing) pushes it more than `force` (N) along the way the
/// person's hand, seen now, moves, and that motion is more than
/// `significance` standard deviations of its speed. In any direction, not only toward where the
/// hand came from: a box drawn up and back past a finger pushed it 12 N
/// along the hand's way but 8 N across the floor toward its home
/// (g1063_00185). RT safe.
bool carriedThrough(const HandoverContext& ctx, double force, double significance);
/// The person's hand, seen now, moves back toward where it was first seen
/// (HandoverContext::home_hand; its velocity has a positive component that
/// way, in 3D): a hand that leaves rather than one that brings the object
/// elsewhere. False when either is unknown. RT safe.
bool goingHome(const HandoverContext& ctx);
/// Position error (m) and rotation angle error (rad) between two poses.
double positionError(const Isometry& a, const Isometry& b);
double rotationError(const Isometry& a, const Isometry& b);
/// TCP pose, orientation and linear-speed errors against the tracking target
/// all below the given tolerances.
bool alignedWithTarget(const HandoverInput& in, double pos_tol, double rot_tol, double speed_tol);
/// The TCP's position and orientation errors against the tracking target
/// within tolerance now and `lead` s ahead: the position moving on at the
/// velocity it has against the target, the turn grown by its relative angular
/// speed whichever way it turns (a close commanded now meets the object when
/// the fingers get there, lead s later: where the TCP is then is what counts,
/// not how fast it still moves; the tracking decelerates, so the straight
/// line is the worse case). RT safe.
bool alignedWhenClosed(const HandoverInput& in, double pos_tol, double rot_tol, double lead);

/// Errors of the object the gripper holds (ObjectInfo::grasp_in_object, the
/// TCP being the grasp frame) between the TCP at `a` and at `b`, as a person
/// taking it sees them: the position of its origin (m), and its orientation
/// (rad) up to the symmetry of its shape: none for a sphere, the direction of
/// the axis for a cylinder (either end first), the whole rotation for a box
/// or an unknown shape.
double heldObjectPositionError(const Isometry& a, const Isometry& b, const ObjectInfo& object);
double heldObjectRotationError(const Isometry& a, const Isometry& b, const ObjectInfo& object);
/// alignedWithTarget for a held object being presented: the same speed test,
/// the position and orientation tests on the object (heldObject*Error), so a
/// ball is presented wherever the gripper's roll settles.
bool presentedAtTarget(const HandoverInput& in, const ObjectInfo& object, double pos_tol, double rot_tol,
                       double speed_tol);

}  // namespace handover::fsm
