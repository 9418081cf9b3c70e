// An approach that the arm's local motion cannot finish: following the
// tracking task's gradient, a joint has run into its limit, and the TCP makes
// no progress toward a target that the planner's inverse kinematics does
// reach (a low box taken from the side: joint 6 at its limit 4 cm short of
// the pre-grasp until the person gave up). The arm then moves in joint space
// to the planner's configuration for the target (the posture task alone,
// tracking off) and tracks again from there.
// A stall with every joint free and the gripper beside the object it lines
// up on (the TCP past its line-up point and off the approach line) is the
// object in the way, not a limit: a joint-space move would go through it.
// The approach then takes a detour (detouring()): it lines up from in front
// of the object again. RT safe.
#pragma once

#include <limits>

#include "fsm/handover/controller_handle.hpp"
#include "fsm/handover/handover_state.hpp"

namespace handover::fsm {

class StallRecovery {
 public:
  /// Reads the optional key stall_time (s): no progress toward the target
  /// for that long is a stall. Absent: off.
  void configure(const YamlReader& def);
  void restart(double time);
  /// Moving in joint space (tracking off).
  bool moving() const { return moving_; }
  /// One tracking cycle: `error` (m) from the TCP to the tracked target;
  /// `at_rest` the target is at rest; `planned` the planner reaches it now;
  /// `beside` the gripper stands beside the object it lines up on. Starts the
  /// joint-space move (to `hand` ? the presentation's : the grasp's IK
  /// configuration, the pre-target's while backed off) when it stalled at a
  /// joint limit with a plan, the detour when it stalled beside the object.
  void watch(HandoverContext& ctx, ControllerHandle& ctrl, bool hand, double error, bool at_rest, bool planned,
             bool beside);
  /// Stalled beside the object: the caller lines up from in front of it
  /// again, and ends the detour (restart) once back on the approach line.
  bool detouring() const { return detour_; }
  /// One joint-space cycle: true once the move is over (at the
  /// configuration, too long, or the target moved or changed): the caller
  /// tracks again.
  bool finished(const HandoverContext& ctx, bool settled, int plan_index);

 private:
  /// m: less is no progress (the sensor's noise moves the target by mm)
  static constexpr double kProgress = 0.01;
  /// rad: every joint this near its goal has arrived
  static constexpr double kArrived = 0.05;
  /// rad: a joint this near its position limit holds the arm there (the
  /// limit's damper); short of a target with every joint free, something
  /// else holds it (the object, the person: a move in joint space went
  /// through them)
  static constexpr double kAtLimit = 0.1;
  double stall_time_ = -1.0;
  double best_ = std::numeric_limits<double>::infinity();
  double best_time_ = 0.0;
  double started_ = 0.0;
  bool moving_ = false;
  bool detour_ = false;
  int index_ = -1;       ///< the plan's candidate when the move started
  Vector7 goal_ = Vector7::Zero();
};

}  // namespace handover::fsm
