#include "fsm/handover/common_states.hpp"

#include <algorithm>
#include <cmath>

#include "fsm/handover/lift_off.hpp"
#include "fsm/handover/perception_checks.hpp"
#include "fsm/handover/timed_move.hpp"

namespace handover::fsm {

namespace {
const Isometry& namedPose(const HandoverParams& p, const std::string& name) {
  if (name == "safe") return p.safe_pose;
  if (name == "ready") return p.ready_pose;
  return p.stow_pose;
}
constexpr double kDeg = M_PI / 180.0;
}  // namespace

SelectDirection::SelectDirection()
    : take_(declareOutput("Take")), give_(declareOutput("Give")), exchanged_(declareOutput("Exchanged")) {}

bool SelectDirection::onRun(HandoverContext& ctx) {
  if (ctx.exchanged) setOutput(exchanged_);
  else setOutput(ctx.in.holds_object ? give_ : take_);
  return true;
}

Rest::Rest() = default;

void Rest::configure(const YamlReader& def) {
  const std::string o = def.child("outcome").asEnum({"success", "aborted", "failed"});
  outcome_ = o == "success" ? "success" : (o == "aborted" ? "aborted" : "failed");
  declareOutput("Never");  // a final state; declared so the table can be checked
}

void Rest::onStart(HandoverContext& ctx) {
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(ObservationTarget::kNone);
  ctrl().setPoseTarget(ctx.in.tcp_pose);
  ctx.stats.outcome = outcome_;
  if (outcome_[0] == 's') ++ctx.stats.handovers;
}

bool Rest::onRun(HandoverContext& ctx) {
  (void)ctx;
  return false;
}

Retract::Retract() : stowed_(declareOutput("Stowed")) {}

void Retract::configure(const YamlReader& def) {
  pose_ = def.child("pose").asEnum({"stow", "safe", "ready"});
  pos_tol_ = readPositive(def, "position_tolerance", 0.5);
  rot_tol_ = readPositive(def, "orientation_tolerance_deg", 180.0) * kDeg;
  settle_speed_ = readPositive(def, "settle_speed", 1.0);
  if (auto k = def.optionalChild("keep_yaw")) keep_yaw_ = k->asBool();
  if (auto lift = def.optionalChild("lift_off")) {
    lift_distance_ = readPositive(*lift, "distance", 0.3);
    lift_elevation_ = readPositive(*lift, "elevation_deg", 90.0) * kDeg;
    lift_tolerance_ = readPositive(*lift, "tolerance", lift_distance_);
    lift_max_time_ = readPositive(*lift, "max_time", 5.0);
    if (auto timed = lift->optionalChild("timed")) lift_timed_ = timed->asBool();
  }
}

void Retract::onStart(HandoverContext& ctx) {
  Isometry goal = namedPose(*ctx.params, pose_);
  if (keep_yaw_) {
    // the named pose turned about the vertical to the TCP's current turn: no
    // pointless wrist rotation while carrying the object away
    const Eigen::Matrix3d M = ctx.in.tcp_pose.linear() * goal.linear().transpose();
    const double yaw = std::atan2(M(1, 0) - M(0, 1), M(0, 0) + M(1, 1));
    goal.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * goal.linear();
  }
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(ObservationTarget::kNone);
  named_goal_ = goal;
  up_axis_ = handedUpAxis(ctx);  // after a take
  // lift the held object off the person's hand first (lift_off.hpp); also when
  // the stow pose is higher: the carry's straight line in joint space may still
  // dip the object on its way (by up to 14 cm on the benchmark)
  const Isometry& tcp = ctx.in.tcp_pose;
  lifting_ = lift_distance_ > 0.0 && ctx.ledger->payloadSet();
  if (!lifting_) {
    carry_.start(ctx, ctrl(), named_goal_, up_axis_);
    return;
  }
  lift_from_ = tcp.translation();
  lift_direction_ = liftOffDirection(tcp, lift_elevation_);
  lift_start_ = tcp;
  // timed: a minimum-jerk profile whose acceleration the grip holds
  lift_duration_ = lift_timed_ ? minimumJerkDuration(lift_distance_, ctx.params->grip_acceleration,
                                                     ctx.params->carry_min_duration)
                               : 0.0;
  Isometry lifted = tcp;
  if (lift_duration_ <= 0.0) lifted.translation() += lift_distance_ * lift_direction_;
  ctrl().setPoseTarget(lifted);
}

bool Retract::onRun(HandoverContext& ctx) {
  if (lifting_ && lift_duration_ > 0.0) {
    // the timed lift-off: along its profile, then the carry from rest
    Vector3 lifted, lift_velocity;
    minimumJerkAlong(lift_distance_, lift_duration_, elapsed(ctx), lift_direction_, lifted, lift_velocity);
    Isometry goal = lift_start_;
    goal.translation() += lifted;
    Vector6 velocity = Vector6::Zero();
    velocity.head<3>() = lift_velocity;
    ctrl().setPoseTarget(goal, velocity);
    if (elapsed(ctx) < std::min(lift_duration_, lift_max_time_)) return false;
    lifting_ = false;
    carry_.start(ctx, ctrl(), named_goal_, up_axis_);
  } else if (lifting_) {
    // within `tolerance` of the lift-off point the carry takes over from a TCP
    // still moving up and back: no stop between the two
    const double lifted = (ctx.in.tcp_pose.translation() - lift_from_).dot(lift_direction_);
    if (lifted < lift_distance_ - lift_tolerance_ && elapsed(ctx) < lift_max_time_) return false;
    lifting_ = false;
    carry_.start(ctx, ctrl(), named_goal_, up_axis_);
  }
  carry_.update(ctx, ctrl());
  if (carry_.waiting()) return false;
  const Isometry& goal = carry_.goal();
  if (positionError(ctx.in.tcp_pose, goal) <= pos_tol_ && rotationError(ctx.in.tcp_pose, goal) <= rot_tol_ &&
      ctx.in.tcp_velocity.head<3>().norm() <= settle_speed_) {
    setOutput(stowed_);
    return true;
  }
  return false;
}

void Retract::onTeardown(HandoverContext& ctx) { carry_.stop(ctx); }

Retreat::Retreat() : retry_(declareOutput("Retry")), give_up_(declareOutput("GiveUp")) {}

void Retreat::configure(const YamlReader& def) {
  open_ = def.child("gripper").asEnum({"keep", "open"}) == "open";
  pos_tol_ = readPositive(def, "position_tolerance", 0.5);
  settle_speed_ = readPositive(def, "settle_speed", 1.0);
  if (def.optionalChild("max_time")) max_time_ = readPositive(def, "max_time", 60.0);
}

void Retreat::onStart(HandoverContext& ctx) {
  ++ctx.stats.aborts;
  if (open_) ctrl().setGripper(ctx.params->gripper_open_width, ctx.params->gripper_force);
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(ObservationTarget::kNone);
  // holding on after an abort: only a give still holds the object here
  carry_.start(ctx, ctrl(), ctx.params->safe_pose, presentedUpAxis(ctx));
}

bool Retreat::onRun(HandoverContext& ctx) {
  carry_.update(ctx, ctrl());
  // a retreat blocked short of its pose (a person in the way, a pose the
  // wrist cannot reach) ends as one that got there: held at a joint limit
  // for 9-14 s, the arm had retreated as far as it could long before
  const bool settled = !carry_.waiting() && positionError(ctx.in.tcp_pose, carry_.goal()) <= pos_tol_ &&
                       ctx.in.tcp_velocity.head<3>().norm() <= settle_speed_;
  if (!settled && elapsed(ctx) < max_time_) return false;
  if (ctx.stats.retries < ctx.params->max_retries) {
    ctx.retry_pending = true;
    setOutput(retry_);
  } else {
    setOutput(give_up_);
  }
  return true;
}

void Retreat::onTeardown(HandoverContext& ctx) { carry_.stop(ctx); }

}  // namespace handover::fsm
