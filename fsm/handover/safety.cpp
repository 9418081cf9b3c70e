#include "fsm/handover/safety.hpp"

#include "fsm/handover/perception_checks.hpp"

namespace handover::fsm {

void HumanTooClose::configure(const YamlReader& def) {
  const YamlReader d = def.child("distance");
  distance_ = d.checkRange(d.asDouble(), 0.0, 2.0);
  const YamlReader g = def.child("grasp_zone_radius");
  grasp_zone_ = g.checkRange(g.asDouble(), 0.0, 1.0);
}

bool personTooClose(const HandoverContext& h, double distance, double grasp_zone) {
  if (!(h.in.human_distance < distance)) return false;
  if (h.in.arm_distance < distance) return true;
  const bool near_tcp = positionError(h.in.hand.pose, h.in.tcp_pose) <= grasp_zone;
  const bool near_target = h.in.observed_target != ObservationTarget::kNone &&
                           positionError(h.in.hand.pose, h.in.target_pose) <= grasp_zone;
  // the hand that holds the object the robot reaches for is the meeting point, wherever on a
  // long object the grasp lies (a bottle's cap is 15 cm from the fist that holds it)
  const bool holds_target = h.in.observed_target == ObservationTarget::kObject && h.in.object.valid &&
                            positionError(h.in.hand.pose, h.in.object.pose) <= grasp_zone;
  return !(h.in.hand.valid && (near_tcp || near_target || holds_target));
}

bool HumanTooClose::evaluate(Context& ctx) {
  return personTooClose(static_cast<HandoverContext&>(ctx), distance_, grasp_zone_);
}

SafetyStop::SafetyStop() : clear_(declareOutput("Clear")) {}

void SafetyStop::configure(const YamlReader& def) {
  clear_distance_ = readPositive(def, "clear_distance", 2.0);
  clear_time_ = readRange(def, "clear_time", 0.0, 10.0);
  if (def.has("grasp_zone_radius")) grasp_zone_ = readRange(def, "grasp_zone_radius", 0.0, 1.0);
  if (def.has("yield_after")) yield_after_ = readRange(def, "yield_after", 0.0, 60.0);
}

void SafetyStop::onStart(HandoverContext& ctx) {
  since_ = -1.0;
  stopped_at_ = ctx.time;
  yielding_ = false;
  ++ctx.stats.safety_stops;
  ctrl().enableTracking(false);
  ctrl().setPoseTarget(ctx.in.tcp_pose);
}

bool SafetyStop::onRun(HandoverContext& ctx) {
  if (personTooClose(ctx, clear_distance_, grasp_zone_)) {
    since_ = -1.0;
    if (!yielding_ && yield_after_ >= 0.0 && ctx.time - stopped_at_ >= yield_after_) {
      Isometry back = ctx.in.tcp_pose;
      back.translation() = ctx.params->safe_pose.translation();
      ctrl().setPoseTarget(back);
      yielding_ = true;
    }
    return false;
  }
  if (since_ < 0.0) since_ = ctx.time;
  if (ctx.time - since_ < clear_time_) return false;
  setOutput(clear_);
  return true;
}

SlowDown::SlowDown() { declareOutput("Never"); }

void SlowDown::configure(const YamlReader& def) { scale_ = readRange(def, "speed_scale", 0.0, 1.0); }

void SlowDown::onStart(HandoverContext& ctx) {
  (void)ctx;
  ctrl().setSpeedScale(scale_);
}

bool SlowDown::onRun(HandoverContext& ctx) {
  (void)ctx;
  return false;
}

}  // namespace handover::fsm
