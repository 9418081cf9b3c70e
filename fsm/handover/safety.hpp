// The safety layer of the handover machine (used as interrupts).
#pragma once

#include "fsm/core/condition.hpp"
#include "fsm/handover/handover_state.hpp"

namespace handover::fsm {

/// True when the person is closer to the robot than `distance` (m) where it
/// matters: the forearm or upper arm anywhere, or the hand outside the grasp
/// zone. The grasp zone is within `grasp_zone` (m) of the TCP or, while the
/// observation follows a target, of the tracking target frame, or the hand
/// holds the object the observation follows (within `grasp_zone` of it):
/// there the hand is close on purpose (collision constraints still keep it
/// untouched).
bool personTooClose(const HandoverContext& h, double distance, double grasp_zone);

/// Holds while personTooClose(distance, grasp_zone_radius).
class HumanTooClose : public Condition {
 public:
  void configure(const YamlReader& def) override;
  bool evaluate(Context& ctx) override;

 private:
  double distance_ = 0.1, grasp_zone_ = 0.15;
};

/// [Clear] Preempting stop: tracking off, TCP held where it is, until the
/// person is no longer too close (personTooClose with clear_distance and
/// grasp_zone_radius) for clear_time. Counts the stop. The gripper is not
/// touched. With yield_after, a person still too close after that long
/// stopped is given room: the TCP backs off toward params.poses.safe's
/// position, keeping its orientation, until they are clear. (Held still, a
/// receiver whose hand waited beside the wrist for the object and a robot
/// waiting for that hand to go stayed so until the run's end.) The collision
/// constraints stay on while it backs off.
/// Keys: clear_distance (m), clear_time (s), grasp_zone_radius (m,
/// optional, 0.15), yield_after (s, optional: never).
class SafetyStop : public HandoverState {
 public:
  SafetyStop();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  int clear_;
  double clear_distance_ = 0.2, clear_time_ = 0.5, grasp_zone_ = 0.15;
  double yield_after_ = -1.0;  ///< s, < 0: never
  double since_ = -1.0;
  double stopped_at_ = 0.0;
  bool yielding_ = false;
};

/// Overlay: scales the controller's speed while active; its teardown puts
/// the previous scale back. Keys: speed_scale (0..1).
class SlowDown : public HandoverState {
 public:
  SlowDown();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  double scale_ = 0.3;
};

}  // namespace handover::fsm
