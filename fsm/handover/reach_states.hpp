// States for the cycle's other jobs, built from the same mechanism as the
// handover (HandoverState, the scoped ledger, a state table in YAML), so the
// paper's experiment, `handover hold` and the closed-loop tests run the very
// same runtime::HandoverCycle::step as a handover, with their own tables:
// config/fsm_reach.yaml, config/fsm_hold.yaml (docs/architecture.md).
// Frames: world; SI units. Real-time: onRun is RT safe; configure is not.
#pragma once

#include <optional>

#include "fsm/handover/handover_state.hpp"

namespace handover::fsm {

/// The paper's reaching phase (section III): the arm meets the object in the
/// person's hand at its PRE-GRASP frame (the grasp backed off by `standoff`
/// along its own approach axis), gripper open; it never closes and never
/// ends. The observed frame starts where the tracking target is the TCP (no
/// pull before the first sample) and jumps onto the first object sample (the
/// observer starts on the data). Keys:
///   standoff: m (default 0.08, as the handover's Approach)
///   follow:   tracking  - observation task -> trajectory-tracking task (the method)
///             set_point - the pose task toward the pre-grasp TCP pose of the
///                         latest object sample, moved only when a new sample
///                         arrives, no feed-forward (the paper's baseline);
///                         the observation task runs too (for the logs).
/// Gains are the controller config's (tracking, pose_task).
class Reach : public HandoverState {
 public:
  Reach();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  double standoff_ = 0.08;
  bool set_point_ = false;
  bool on_data_ = false;      ///< the observed frame was put on the first sample
  double last_stamp_ = -1.0;  ///< the sample the set-point was taken from
};

/// Holds still, never ends: tracking off, observation none. Keys (optional):
///   posture: [7 rad]           the posture task's target (default: the configured one)
///   pose:    {pos: m, rpy: rad} the pose task toward this TCP pose (world; default: off)
class Hold : public HandoverState {
 public:
  Hold();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  std::optional<Vector7> posture_;
  std::optional<Isometry> pose_;
};

}  // namespace handover::fsm
