#include "fsm/handover/back_out.hpp"

#include "fsm/handover/perception_checks.hpp"

namespace handover::fsm {

BackOut::BackOut() : clear_(declareOutput("Clear")) {}

void BackOut::configure(const YamlReader& def) {
  distance_ = readPositive(def, "distance", 0.3);
  pos_tol_ = readPositive(def, "position_tolerance", 0.1);
}

void BackOut::onStart(HandoverContext& ctx) {
  start_ = ctx.in.tcp_pose;
  goal_ = start_;
  goal_.translation() -= distance_ * start_.linear().col(2);
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(ObservationTarget::kNone);
  ctrl().setPoseTarget(goal_);
}

bool BackOut::onRun(HandoverContext& ctx) {
  const Vector3 axis = start_.linear().col(2);
  const double backed = -(ctx.in.tcp_pose.translation() - start_.translation()).dot(axis);
  if (positionError(ctx.in.tcp_pose, goal_) <= pos_tol_ || backed >= distance_ - pos_tol_) {
    setOutput(clear_);
    return true;
  }
  return false;
}

}  // namespace handover::fsm
