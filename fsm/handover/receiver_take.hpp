// A receiver who takes the object the robot still carries, before the robot
// presented it: their hand closed on it where the robot holds it (the robot
// waiting at its ready pose with the object hanging into their reach, or on
// its way to them) and pulls it toward themselves. That is the handover, and
// the robot lets go (Release) instead of holding on against the pull, taking
// the hand that leaves with the object for a withdrawal, and losing it. RT safe.
#pragma once

#include "fsm/handover/handover_state.hpp"
#include "fsm/handover/take_back.hpp"

namespace handover::fsm {

/// The receiver's hand (its grip point, as sensed) within `reach` (m) of the
/// surface of the object the robot holds (HandoverContext::objectInTcp at the
/// TCP; the object's centre plus `reach` when its shape is unknown). RT safe.
bool handAtHeldObject(const HandoverContext& ctx, double reach);

/// m: a hand holding the object has its grip point within a palm's half
/// width of its surface (the simulated person takes hold within 3 cm; the
/// sensor's noise on top)
constexpr double kReceiverGripReach = 0.05;

/// A pull on the presented object can be the receiver's: their hand, where
/// it is seen (fresh), is at the object (handAtHeldObject, kReceiverGripReach);
/// unseen, or the object's shape unknown, the force alone decides. A hand that moved to another place
/// brushed the object on its way, the robot read a pull and let go of an
/// object nobody held. RT safe.
bool receiverMayHoldIt(const HandoverContext& ctx);

/// The pull of a receiver who holds the carried object: pulledBack (the
/// force across the floor toward where their hand came from, params.withdraw
/// take_back_force, the hand moving that way faster than a hand at rest)
/// with the hand at the object, for `hold_time` s. Off unless the state's
/// definition has `pull_hold_time`.
class ReceiverTake {
 public:
  /// Reads the optional key pull_hold_time (s); true when it is there (the
  /// state then declares its output `Pulled`).
  bool configure(const YamlReader& def);
  void restart() { pull_.restart(); }
  /// True once the receiver has pulled the object they hold for the hold
  /// time (never when disabled). RT safe.
  bool taken(const HandoverContext& ctx);

 private:
  /// m/s: the hand that pulls moves (the contract's hand at rest is slower):
  /// an arm carrying the object into a hand that stands still pushes it
  /// just as hard (150 N seen), and that is no take
  static constexpr double kPullSpeed = 0.05;
  bool enabled_ = false;
  double hold_time_ = 0.05;
  TakeBack pull_;
};

}  // namespace handover::fsm
