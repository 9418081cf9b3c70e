// Robot to human: the robot presents the object, the person takes it.
#pragma once

#include "fsm/handover/release_ride.hpp"
#include "fsm/handover/handover_state.hpp"
#include "fsm/handover/held_object_goal.hpp"
#include "fsm/handover/receiver_take.hpp"
#include "fsm/handover/rest_window.hpp"
#include "fsm/handover/withdrawal_watch.hpp"

namespace handover::fsm {

/// [Ready] Keeps the object gripped (closes, sets the payload) and moves to
/// params.ready_pose while observing the hand; the object goes upright near
/// it when a planner is present (held_object_goal.hpp).
/// Also ready where it stands once a collision row with the person has been
/// engaged for blocked_time (s) (HandoverInput::person_constraint_engaged):
/// a receiver already there holds the arm off the ready pose.
/// The placement keeps the arm out of the receiver's way to the object
/// (CarryRequest::receiver_stop): it is asked for once the person is seen,
/// or after wait_for_person (s) without them (heading for the ready pose
/// meanwhile).
/// [Pulled] with pull_hold_time (s): a receiver who takes hold of the object
/// on its way and pulls it (receiver_take.hpp).
/// Keys: position_tolerance (m), settle_speed (m/s), blocked_time (s; absent: never),
/// wait_for_person (s), pull_hold_time (s; absent: off).
class HoldReady : public HandoverState {
 public:
  HoldReady();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;
  void onTeardown(HandoverContext& ctx) override;

 private:
  int ready_, pulled_ = -1;
  ReceiverTake take_;  ///< a receiver who takes the object on its way
  double pos_tol_ = 0.03, settle_speed_ = 0.03;
  /// s an arm held off by the person (HandoverInput::person_constraint_engaged)
  /// waits before it is ready where it is; negative = never
  double blocked_time_ = -1.0;
  double blocked_since_ = -1.0;
  double wait_for_person_ = 0.2;  ///< s
  double started_ = 0.0;          ///< s, when the state started
  bool carrying_ = false;         ///< the carry (and its placement request) has started
  void startCarry(HandoverContext& ctx);
  HeldObjectCarry carry_;  ///< the ready pose, or an upright placement of the object near it
};

/// [Presented, Withdrawn] Tracks the presentation frame (still relative to
/// the hand) until position and orientation errors stay within tolerance and,
/// over settle_time, the TCP keeps its place against the target and the
/// receiver's hand rests, each within speed_tolerance * settle_time of where
/// it was (displacements, not speeds: under a 30 Hz, 1 cm tracker the target,
/// and the arm following it, jittered at 0.1-0.3 m/s around a hand at rest;
/// never presented, and the receiver never took an object that would not keep
/// still: outsider e_46). Keys: position_tolerance (m),
/// orientation_tolerance_deg, speed_tolerance (m/s), settle_time (s);
/// lift_speed (m/s, optional): the approach's descent onto the palm ends,
/// its shift going to zero at that speed (presentation_descent.hpp); the
/// errors are those to the presentation itself, not to the raised target.
class Present : public HandoverState {
 public:
  Present();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  int presented_, withdrawn_, pulled_;
  double pos_tol_ = 0.02, rot_tol_ = 0.2, speed_tol_ = 0.05, settle_time_ = 0.2;
  double pull_threshold_ = 0.0, pull_hold_ = 0.05;  ///< N (0 = off), s
  double lift_speed_ = 0.4;                         ///< m/s (presentation_descent.hpp)
  double pull_since_ = -1.0, last_time_ = 0.0;
  RestWindow rest_;   ///< the receiver's hand at rest (settle window)
  RestWindow keeps_;  ///< the TCP keeping its place against the target (settle window)
  WithdrawalWatch withdrawal_;  ///< the receiver leaves: Withdrawn
};

/// [Pulled] Holds the TCP still (with stiff_hold: true, as stiffly as
/// Release does, at the tracking's closing gains: the weak wrist of the pose
/// task's own gains drifted under the uncompensated load) and records the filtered force (object and
/// hand weight included); pulled when the filtered force differs from it by
/// more than pull_threshold for hold_time. Set a `timeout` for "no pull".
/// With `moved_time` (s), [Moved]: the receiver's hand, seen, has gone more
/// than 5 cm from where it was when the wait began, and for that long either
/// the object is not in its grip (receiverMayHoldIt) or the hand rests again
/// (rest_speed x moved_time over a moved_time window) without pulling: they
/// put their hand elsewhere to take it, and the object is presented there
/// again (a receiver who moved their hand 9 cm waited 10 s for an object held
/// still where their hand had been, and gave up: g421_00463; one whose hand
/// came on 6 cm past the presentation and stopped beside the gripper, near
/// the ball but not at it, waited 6 s, and the gripper drifted into it:
/// g929_00162). A hand that grips and pulls pulls within the window.
/// Keys: pull_threshold (N), hold_time (s), moved_time (s, optional),
/// rest_speed (m/s, with moved_time, default 0.05), stiff_hold (bool, default false).
class DetectPull : public HandoverState {
 public:
  DetectPull();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  bool handMoved(HandoverContext& ctx);

  int pulled_, moved_ = -1;
  double threshold_ = 3.0, hold_time_ = 0.05, moved_time_ = 0.0, rest_speed_ = 0.05;
  bool stiff_hold_ = false;  ///< held at the tracking's closing gains, not the pose task's own
  double since_ = -1.0, moved_since_ = -1.0;
  Vector3 hand_at_start_ = Vector3::Zero();
  RestWindow hand_rest_;  ///< the receiver's hand at rest again (moved_time window)
  bool hand_seen_at_start_ = false;
};

/// [Opened] Opens the gripper, holding the TCP where it was, moved along with
/// the object as the receiver takes it (ReleaseRide);
/// done when the fingers are open wider than min_width. Keys: min_width (m).
class Release : public HandoverState {
 public:
  Release();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  int opened_;
  double min_width_ = 0.07;
  Isometry hold_ = Isometry::Identity();
  ReleaseRide ride_;
};

/// [Gone] Fingers open wider than min_width and at least gone_fraction of
/// the object's weight left the sensor (relative to the force recorded by
/// DetectPull), or the robot's load share is at most 1 - gone_fraction (a
/// receiver who already carried part of the weight when DetectPull recorded
/// the force), for hold_time; then clears the payload. Holds the TCP as
/// Release does (riding along with the object being taken).
/// Keys: min_width (m), gone_fraction, hold_time (s).
class ConfirmGone : public HandoverState {
 public:
  ConfirmGone();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  int gone_;
  double min_width_ = 0.07, fraction_ = 0.7, hold_time_ = 0.1;
  double since_ = -1.0;
  Isometry hold_ = Isometry::Identity();
  ReleaseRide ride_;
};

}  // namespace handover::fsm
