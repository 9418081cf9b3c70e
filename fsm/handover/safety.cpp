#include "fsm/handover/safety.hpp"

#include "fsm/handover/perception_checks.hpp"

namespace handover::fsm {

void HumanTooClose::configure(const YamlReader& def) {
  const YamlReader d = def.child("distance");
  distance_ = d.checkRange(d.asDouble(), 0.0, 2.0);
  const YamlReader g = def.child("grasp_zone_radius");
  grasp_zone_ = g.checkRange(g.asDouble(), 0.0, 1.0);
}

bool HumanTooClose::evaluate(Context& ctx) {
  const HandoverContext& h = static_cast<HandoverContext&>(ctx);
  if (!(h.in.human_distance < distance_)) return false;
  const bool in_grasp_zone =
      h.in.hand.valid && positionError(h.in.hand.pose, h.in.tcp_pose) <= grasp_zone_;
  return !in_grasp_zone;
}

SafetyStop::SafetyStop() : clear_(declareOutput("Clear")) {}

void SafetyStop::configure(const YamlReader& def) {
  clear_distance_ = readPositive(def, "clear_distance", 2.0);
  clear_time_ = readRange(def, "clear_time", 0.0, 10.0);
}

void SafetyStop::onStart(HandoverContext& ctx) {
  since_ = -1.0;
  ++ctx.stats.safety_stops;
  ctrl().enableTracking(false);
  ctrl().setPoseTarget(ctx.in.tcp_pose);
}

bool SafetyStop::onRun(HandoverContext& ctx) {
  if (!(ctx.in.human_distance > clear_distance_)) {
    since_ = -1.0;
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
