#include "fsm/handover/back_out.hpp"

#include <algorithm>

namespace handover::fsm {

BackOut::BackOut() : clear_(declareOutput("Clear")) {}

void BackOut::configure(const YamlReader& def) {
  distance_ = readPositive(def, "distance", 0.3);
  pos_tol_ = readPositive(def, "position_tolerance", 0.1);
  yield_force_ = readPositive(def, "yield_force", 200.0);
  yield_rate_ = readRange(def, "yield_rate", 0.0, 1.0);
  yield_distance_ = readRange(def, "yield_distance", 0.0, 0.5);
}

void BackOut::onStart(HandoverContext& ctx) {
  start_ = ctx.in.tcp_pose;
  yielded_.setZero();
  last_time_ = ctx.in.time;
  Isometry goal = start_;
  goal.translation() -= distance_ * start_.linear().col(2);
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(ObservationTarget::kNone);
  ctrl().setPoseTarget(goal);
}

bool BackOut::onRun(HandoverContext& ctx) {
  const double dt = std::max(0.0, ctx.in.time - last_time_);
  last_time_ = ctx.in.time;
  // across the approach axis only: along it the push would undo the backing out
  const Vector3 axis = start_.linear().col(2);
  const Vector3 contact = ctx.in.tool_contact.head<3>();
  const Vector3 push = contact - contact.dot(axis) * axis;
  const double excess = push.norm() - yield_force_;
  if (excess > 0.0 && yielded_.norm() < yield_distance_) {
    yielded_ += (yield_rate_ * excess * dt / push.norm()) * push;
    Isometry goal = start_;
    goal.translation() += yielded_ - distance_ * start_.linear().col(2);
    ctrl().setPoseTarget(goal);
  }
  // progress along the approach axis only (the yield is across it): a
  // sideways push by the person must not hold the fingers in place
  const double backed = -(ctx.in.tcp_pose.translation() - start_.translation()).dot(axis);
  if (backed >= distance_ - pos_tol_) {
    setOutput(clear_);
    return true;
  }
  return false;
}

}  // namespace handover::fsm
