#include "fsm/handover/receiver_take.hpp"

#include "fsm/handover/perception_checks.hpp"

namespace handover::fsm {

bool handAtHeldObject(const HandoverContext& ctx, double reach) {
  if (!fresh(ctx.in.hand, ctx.params->max_data_age)) return false;
  const Isometry object = ctx.in.tcp_pose * ctx.objectInTcp();
  const Vector3 grip = object.inverse() * ctx.in.hand.pose.translation();
  if (!ctx.object.shape.known()) return grip.norm() <= reach;
  return io::signedDistance(ctx.object.shape, grip) <= reach;
}

bool receiverMayHoldIt(const HandoverContext& ctx) {
  if (!fresh(ctx.in.hand, ctx.params->max_data_age) || !ctx.object.shape.known()) return true;
  return handAtHeldObject(ctx, kReceiverGripReach);
}

bool ReceiverTake::configure(const YamlReader& def) {
  enabled_ = def.has("pull_hold_time");
  if (enabled_) hold_time_ = HandoverState::readRange(def, "pull_hold_time", 0.0, 5.0);
  return enabled_;
}

bool ReceiverTake::taken(const HandoverContext& ctx) {
  if (!enabled_ || !handAtHeldObject(ctx, kReceiverGripReach)) {
    pull_.restart();
    return false;
  }
  return pull_.pulled(ctx, hold_time_, kPullSpeed);
}

}  // namespace handover::fsm
