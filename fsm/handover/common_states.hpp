// States used by both directions. Outputs in brackets.
#pragma once

#include "fsm/handover/handover_state.hpp"
#include "fsm/handover/held_object_goal.hpp"

namespace handover::fsm {

/// [Take, Give, Exchanged] Give when the controller says the gripper holds
/// the object; Exchanged once it has changed hands (HandoverContext::
/// exchanged: the machine restarted after a safety stop in the retract).
class SelectDirection : public HandoverState {
 public:
  SelectDirection();
  bool onRun(HandoverContext& ctx) override;

 private:
  int take_, give_, exchanged_;
};

/// Final state, never done: holds the TCP where it is, tracking off, and
/// publishes the outcome. Keys: outcome: success | aborted | failed.
class Rest : public HandoverState {
 public:
  Rest();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  const char* outcome_ = "aborted";
};

/// [Stowed] Carries the TCP to a named pose (stow | safe | ready), tracking
/// off, observation none; a held object goes upright near it when a planner
/// is present (held_object_goal.hpp: the placement is asked for at the start
/// and adopted once answered). Keys: pose, position_tolerance (m),
/// orientation_tolerance_deg, settle_speed (m/s), keep_yaw (bool), lift_off
/// (optional, after a take: {distance: m, elevation_deg, tolerance: m,
/// max_time: s}; with the object held, the TCP first moves `distance` along
/// liftOffDirection (lift_off.hpp), orientation held, and the carry starts
/// within `tolerance` of that point or after max_time, whichever is first;
/// with `timed: true` the lift-off follows a minimum-jerk profile whose peak
/// acceleration is the grip's (params.gripper.grip.acceleration), at least
/// params.carry.min_duration long, its rate fed forward, and the carry
/// starts at its end).
class Retract : public HandoverState {
 public:
  Retract();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;
  void onTeardown(HandoverContext& ctx) override;

 private:
  int stowed_;
  std::string pose_ = "stow";
  double pos_tol_ = 0.02, rot_tol_ = 0.1, settle_speed_ = 0.02;
  bool keep_yaw_ = false;               ///< keep the TCP's turn about the vertical
  HeldObjectCarry carry_;               ///< the named pose, or an upright placement of a held object near it
  // the lift-off (lift_off.hpp); distance 0 = none
  double lift_distance_ = 0.0, lift_elevation_ = 0.0, lift_tolerance_ = 0.0, lift_max_time_ = 0.0;
  bool lifting_ = false, lift_timed_ = false;
  double lift_duration_ = 0.0;  ///< s of the timed lift-off (0: a set-point step)
  Vector3 lift_from_ = Vector3::Zero(), lift_direction_ = Vector3::Zero();
  Isometry lift_start_ = Isometry::Identity();  ///< the TCP when the lift-off began
  Isometry named_goal_ = Isometry::Identity();  ///< the carry's named pose, kept while lifting
  Vector3 up_axis_ = Vector3::UnitZ();          ///< the object's way up when the state started
};

/// [Retry, GiveUp] After an abort: counts it, goes to the safe pose, then
/// retries while params.max_retries allows. Keys: gripper: keep | open
/// (keep never drops a held object; open lets the person keep theirs),
/// position_tolerance (m), settle_speed (m/s), max_time (s: a retreat still
/// short of its pose then - blocked by a person or a joint limit - ends as
/// one that got there).
class Retreat : public HandoverState {
 public:
  Retreat();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;
  void onTeardown(HandoverContext& ctx) override;

 private:
  int retry_, give_up_;
  bool open_ = false;
  double pos_tol_ = 0.03, settle_speed_ = 0.03;
  double max_time_ = 5.0;  ///< s: a retreat still short of its pose then is as far back as it gets
  HeldObjectCarry carry_;  ///< the safe pose, or an upright placement of a held object near it
};

}  // namespace handover::fsm
