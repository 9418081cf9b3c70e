#include "fsm/handover/back_out.hpp"

namespace handover::fsm {

BackOut::BackOut() : clear_(declareOutput("Clear")) {}

void BackOut::configure(const YamlReader& def) {
  distance_ = readPositive(def, "distance", 0.3);
  pos_tol_ = readPositive(def, "position_tolerance", 0.1);
}

void BackOut::onStart(HandoverContext& ctx) {
  start_ = ctx.in.tcp_pose;
  Isometry goal = start_;
  goal.translation() -= distance_ * start_.linear().col(2);
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(ObservationTarget::kNone);
  ctrl().setPoseTarget(goal);
}

bool BackOut::onRun(HandoverContext& ctx) {
  // progress along the approach axis only: a sideways push by the person
  // must not hold the fingers in place
  const double backed = -(ctx.in.tcp_pose.translation() - start_.translation()).dot(start_.linear().col(2));
  if (backed >= distance_ - pos_tol_) {
    setOutput(clear_);
    return true;
  }
  return false;
}

}  // namespace handover::fsm
