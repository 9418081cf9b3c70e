#include "fsm/handover/stall_recovery.hpp"

#include "fsm/handover/tracking_setup.hpp"

namespace handover::fsm {

void StallRecovery::configure(const YamlReader& def) {
  if (def.has("stall_time")) stall_time_ = HandoverState::readPositive(def, "stall_time", 10.0);
}

void StallRecovery::restart(double time) {
  best_ = std::numeric_limits<double>::infinity();
  best_time_ = time;
  moving_ = false;
  detour_ = false;
}

void StallRecovery::watch(HandoverContext& ctx, ControllerHandle& ctrl, bool hand, double error, bool at_rest,
                          bool planned, bool beside) {
  if (stall_time_ <= 0.0) return;
  const TrackedChoice& c = trackedChoice(ctx, hand);
  const bool at_limit = ctx.in.joint_limit_margin <= kAtLimit;
  // at a limit: the planner's configuration is the way out; beside the object: the way in front
  // of it, planned or not (a declared grasp the planner does not reach, g893_00092)
  const bool way_out = at_limit ? planned && c.planned : beside;
  if (detour_ || !at_rest || !way_out || error < best_ - kProgress) {
    best_ = at_rest ? error : std::numeric_limits<double>::infinity();
    best_time_ = ctx.time;
    return;
  }
  if (ctx.time - best_time_ < stall_time_) return;
  if (!at_limit) {
    detour_ = true;  // the object holds it, not a joint: the caller lines up from in front of it again
    return;
  }
  goal_ = ctx.tracking_standoff > 0.0 ? c.q_pre : c.q_target;
  index_ = c.index;
  moving_ = true;
  started_ = ctx.time;
  ctrl.enableTracking(false);
  ctrl.clearPoseTarget();
  ctrl.setPostureTarget(goal_);
}

bool StallRecovery::finished(const HandoverContext& ctx, bool settled, int plan_index) {
  const bool arrived = (ctx.in.q - goal_).cwiseAbs().maxCoeff() < kArrived;
  // as long as the arm took to stall again: it moves, or it is no way out
  const bool too_long = ctx.time - started_ > 2.0 * stall_time_ + 1.0;
  if (!arrived && !too_long && settled && plan_index == index_) return false;
  restart(ctx.time);  // progress is owed again from here
  return true;
}

}  // namespace handover::fsm
