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
}

void StallRecovery::watch(HandoverContext& ctx, ControllerHandle& ctrl, bool hand, double error, bool settled) {
  if (stall_time_ <= 0.0) return;
  const TrackedChoice& c = trackedChoice(ctx, hand);
  if (!settled || !c.planned || error < best_ - kProgress || ctx.in.joint_limit_margin > kAtLimit) {
    best_ = settled ? error : std::numeric_limits<double>::infinity();
    best_time_ = ctx.time;
    return;
  }
  if (ctx.time - best_time_ < stall_time_) return;
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
