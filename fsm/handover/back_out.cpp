#include "fsm/handover/back_out.hpp"

#include <algorithm>

#include "fsm/handover/perception_checks.hpp"
#include "fsm/handover/timed_move.hpp"
#include "interfaces/object_shape.hpp"

namespace handover::fsm {

BackOut::BackOut() : clear_(declareOutput("Clear")) {}

void BackOut::configure(const YamlReader& def) {
  distance_ = readPositive(def, "distance", 0.3);
  duration_ = readPositive(def, "duration", 5.0);
  pos_tol_ = readPositive(def, "position_tolerance", 0.1);
  yield_force_ = readPositive(def, "yield_force", 200.0);
  yield_rate_ = readRange(def, "yield_rate", 0.0, 1.0);
  yield_distance_ = readRange(def, "yield_distance", 0.0, 0.5);
  if (auto o = def.optionalChild("open_gripper")) open_gripper_ = o->asBool();
  if (auto o = def.optionalChild("until_object_clear")) until_object_clear_ = o->asBool();
}

bool BackOut::objectClear(const HandoverContext& ctx) const {
  const SensedBody& seen = ctx.in.object;
  const io::ObjectShape& shape = ctx.object.shape;
  if (shape.kind == io::ObjectShape::Kind::kUnknown || !fresh(seen, ctx.params->max_data_age)) return false;
  const double reach = 0.5 * ctx.params->gripper_open_width + ctx.params->finger_half_span;
  const Isometry tcp_in_object = seen.pose.inverse() * ctx.in.tcp_pose;
  // points along the fingers' axis about a centimetre apart: the reach's radius covers between them
  constexpr int kSegments = 10;
  const double back = distance_, ahead = ctx.params->finger_pad_reach;
  for (int i = 0; i <= kSegments; ++i) {
    const double z = -back + (back + ahead) * i / kSegments;
    if (io::signedDistance(shape, tcp_in_object * Vector3(0.0, 0.0, z)) <= reach) return false;
  }
  return true;
}

void BackOut::onStart(HandoverContext& ctx) {
  start_ = ctx.in.tcp_pose;
  start_time_ = ctx.in.time;
  yielded_.setZero();
  if (open_gripper_) ctrl().setGripper(ctx.params->gripper_open_width, ctx.params->gripper_force);
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
  if (backed >= distance_ - pos_tol_ || (until_object_clear_ && objectClear(ctx))) {
    setOutput(clear_);
    return true;
  }
  return false;
}

}  // namespace handover::fsm
