// Whether the person withdraws what they bring (the offered object, or a
// receiver's hand), judged from evidence that they leave, not from one fast
// move. A person who shifts where they hold the object moves it a few
// centimetres, often fast (the benchmark's `moving` offers: 5-15 cm in
// 0.4-0.9 s, peaks of 0.4-0.7 m/s, some away from the robot); one who leaves
// carries it back toward their body, 30 cm and more. Read off the speed
// alone, the shift was a withdrawal: the robot backed off, waited and came
// back, 3 s lost in most such takes (seed 631: 15 of the 20 slowest takes).
// A dropout is no evidence either: it is mostly an occlusion (the arm itself
// comes between the camera and the hand it meets), so only a body unseen for
// longer than params.stale_timeout has left.
//
// Frames: world. Units: m, m/s. Real-time safe.
#pragma once

#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// Per state that watches for a withdrawal (Approach, Grasp before the
/// close, Present): withdrawn() once a cycle.
class WithdrawalWatch {
 public:
  /// Forgets a motion under way (the state starts).
  void restart() { leaving_ = arrived_ = left_home_ = false; }
  /// The person withdrew the receiver's hand (`hand`) or the offered object:
  /// perception stale for longer than params.stale_timeout, the body outside
  /// the workspace grown by params.withdraw_workspace_margin, or leaving
  /// (leaving(): moving away or heading home faster than withdraw_speed;
  /// only heading home until the body has once been slower than
  /// params.arrive_speed: a reach under way may end far out)
  /// without a pause since it has come params.withdraw_distance (straight
  /// line) from where that motion began, or, heading home, it is within that
  /// distance of home (a reach taken back early is short); or back within
  /// params.withdraw_home_radius of home, however slowly, after it had been
  /// twice that from it since restart(). A short dropout keeps the motion
  /// under way. RT safe.
  bool withdrawn(const HandoverContext& ctx, bool hand);

 private:
  bool leaving_ = false;               ///< a leaving motion is under way
  bool arrived_ = false;               ///< the body has been slower than params.arrive_speed since restart()
  bool left_home_ = false;             ///< it has been 2 params.withdraw_home_radius from home since restart()
  Vector3 from_ = Vector3::Zero();     ///< m, world: where it began
};

}  // namespace handover::fsm
