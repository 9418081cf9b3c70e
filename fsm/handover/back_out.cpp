#include "fsm/handover/back_out.hpp"

#include <algorithm>

#include "fsm/handover/timed_move.hpp"

namespace handover::fsm {

BackOut::BackOut() : clear_(declareOutput("Clear")) {}

void BackOut::configure(const YamlReader& def) {
  distance_ = readPositive(def, "distance", 0.3);
  duration_ = readPositive(def, "duration", 5.0);
  pos_tol_ = readPositive(def, "position_tolerance", 0.1);
  yield_force_ = readPositive(def, "yield_force", 200.0);
  yield_rate_ = readRange(def, "yield_rate", 0.0, 1.0);
  yield_distance_ = readRange(def, "yield_distance", 0.0, 0.5);
}

void BackOut::onStart(HandoverContext& ctx) {
  start_ = ctx.in.tcp_pose;
  start_time_ = ctx.in.time;
  yielded_.setZero();
  ride_.start(ctx);
  last_time_ = ctx.in.time;
  Isometry goal = start_;
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
  Vector6 velocity = Vector6::Zero();
  if (excess > 0.0 && yielded_.norm() < yield_distance_) {
    // the goal's rate fed forward: the arm gives way now, not D / K later
    velocity.head<3>() = (yield_rate_ * excess / push.norm()) * push;
    yielded_ += dt * velocity.head<3>();
  }
  // riding along with the object leaving between the fingers
  Vector3 ride, ride_velocity;
  ride_.follow(ctx.in, ride, ride_velocity);
  velocity.head<3>() += ride_velocity;
  // straight back along the approach axis on a minimum-jerk profile, its rate fed forward
  Vector3 back, back_velocity;
  minimumJerkAlong(distance_, duration_, ctx.in.time - start_time_, -axis, back, back_velocity);
  velocity.head<3>() += back_velocity;
  Isometry goal = start_;
  goal.translation() += yielded_ + ride + back;
  ctrl().setPoseTarget(goal, velocity);
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
