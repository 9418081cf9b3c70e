#include "fsm/handover/perception_checks.hpp"

#include <cmath>

namespace handover::fsm {

double speedToward(const Vector3& center, const SensedBody& body) {
  const Vector3 d = center - body.pose.translation();
  const double n = d.norm();
  if (n < 1e-9) return 0.0;
  return body.velocity.head<3>().dot(d / n);
}

bool fresh(const SensedBody& body, double max_age) { return body.valid && body.age <= max_age; }

bool inWorkspace(const HandoverContext& ctx, bool hand, double margin) {
  const HandoverParams& p = *ctx.params;
  const auto at = [&](const SensedBody& b) { return (p.anticipate_reach ? restPose(b) : b.pose).translation(); };
  if (p.workspace.contains(at(hand ? ctx.in.hand : ctx.in.object), margin)) return true;
  return !hand && fresh(ctx.in.hand, p.max_data_age) && p.workspace.contains(at(ctx.in.hand), margin);
}

const Vector3* homeOf(const HandoverContext& ctx, bool hand) {
  if (hand) return ctx.home_hand_known ? &ctx.home_hand : nullptr;
  return ctx.home_object_known ? &ctx.home_object : nullptr;
}

double farthestFromHome(const HandoverContext& ctx, bool hand) {
  return hand ? ctx.hand_farthest_from_home : ctx.object_farthest_from_home;
}

double fromHome(const HandoverContext& ctx, bool hand) { return hand ? ctx.hand_from_home : ctx.object_from_home; }

bool headingHome(const HandoverContext& ctx, bool hand) {
  // heading there, not only drifting that way: a person who moves the hand on to where they
  // settle was taken for one who withdraws
  const Vector3* home = homeOf(ctx, hand);
  if (home == nullptr) return false;
  const SensedBody& body = hand ? ctx.in.hand : ctx.in.object;
  const double toward = speedToward(*home, body);
  constexpr double kHeading = 0.866;  // cos 30 deg
  return toward > ctx.params->withdraw_speed && toward >= kHeading * body.velocity.head<3>().norm();
}

bool movingAway(const HandoverContext& ctx, bool hand) {
  const SensedBody& body = hand ? ctx.in.hand : ctx.in.object;
  return -speedToward(ctx.params->workspace.center, body) > ctx.params->withdraw_speed;
}

bool leaving(const HandoverContext& ctx, bool hand) {
  // or heading back to where it rested before the reach, away from the workspace centre or not
  return movingAway(ctx, hand) || headingHome(ctx, hand);
}

std::optional<bool> withdrawnAtOnce(const HandoverContext& ctx, bool hand) {
  const HandoverParams& p = *ctx.params;
  const SensedBody& body = hand ? ctx.in.hand : ctx.in.object;
  if (body.age > p.stale_timeout) return true;
  if (!body.valid) return false;  // a short dropout: keep the last decision
  if (!inWorkspace(ctx, hand, p.withdraw_workspace_margin)) return true;
  return std::nullopt;
}

bool withdrawn(const HandoverContext& ctx, bool hand) {
  return withdrawnAtOnce(ctx, hand).value_or(leaving(ctx, hand));
}

bool pulledBack(const HandoverContext& ctx, double force, double hand_speed) {
  if (!ctx.home_hand_known || !fresh(ctx.in.hand, ctx.params->max_data_age)) return false;
  Vector3 d = ctx.home_hand - ctx.in.hand.pose.translation();
  d.z() = 0.0;
  const double n = d.norm();
  if (n < 1e-9) return false;
  d /= n;
  return ctx.interaction.dot(d) > force && ctx.in.hand.velocity.head<3>().dot(d) > hand_speed;
}

bool carriedThrough(const HandoverContext& ctx, double force, double significance) {
  const SensedBody& hand = ctx.in.hand;
  if (!fresh(hand, ctx.params->max_data_age)) return false;
  const Vector3 v = hand.velocity.head<3>();
  const double speed = v.norm();
  if (!(speed > significance * hand.speed_std) || speed < 1e-6) return false;
  return ctx.interaction.dot(v / speed) > force;
}

bool goingHome(const HandoverContext& ctx) {
  if (!ctx.home_hand_known || !fresh(ctx.in.hand, ctx.params->max_data_age)) return false;
  return ctx.in.hand.velocity.head<3>().dot(ctx.home_hand - ctx.in.hand.pose.translation()) > 0.0;
}

double positionError(const Isometry& a, const Isometry& b) {
  return (a.translation() - b.translation()).norm();
}

double rotationError(const Isometry& a, const Isometry& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

namespace {
// m/s: the TCP's linear speed relative to its moving target
double speedAgainstTarget(const HandoverInput& in) {
  return (in.tcp_velocity.head<3>() - in.target_velocity.head<3>()).norm();
}
// the held object's pose when the TCP (its grasp frame) is at `tcp`
Isometry objectPose(const Isometry& tcp, const ObjectInfo& object) { return tcp * object.grasp_in_object.inverse(); }
}  // namespace

bool alignedWithTarget(const HandoverInput& in, double pos_tol, double rot_tol, double speed_tol) {
  const double speed = speedAgainstTarget(in);
  return positionError(in.tcp_pose, in.target_pose) <= pos_tol &&
         rotationError(in.tcp_pose, in.target_pose) <= rot_tol && speed <= speed_tol;
}

bool alignedWhenClosed(const HandoverInput& in, double pos_tol, double rot_tol, double lead) {
  const Vector3 error = in.tcp_pose.translation() - in.target_pose.translation();
  const Vector6 relative = in.tcp_velocity - in.target_velocity;
  const double turn = rotationError(in.tcp_pose, in.target_pose);
  return error.norm() <= pos_tol && (error + lead * relative.head<3>()).norm() <= pos_tol && turn <= rot_tol &&
         turn + lead * relative.tail<3>().norm() <= rot_tol;
}

double heldObjectPositionError(const Isometry& a, const Isometry& b, const ObjectInfo& object) {
  return positionError(objectPose(a, object), objectPose(b, object));
}

double heldObjectRotationError(const Isometry& a, const Isometry& b, const ObjectInfo& object) {
  using Kind = io::ObjectShape::Kind;
  switch (object.shape.kind) {
    case Kind::kSphere:
      return 0.0;
    case Kind::kCylinder: {
      const Vector3 axis_a = objectPose(a, object).linear().col(2);
      const Vector3 axis_b = objectPose(b, object).linear().col(2);
      return std::atan2(axis_a.cross(axis_b).norm(), std::abs(axis_a.dot(axis_b)));  // exact near 0, unlike acos
    }
    case Kind::kBox:
    case Kind::kUnknown:
      break;
  }
  return rotationError(a, b);
}

bool presentedAtTarget(const HandoverInput& in, const ObjectInfo& object, double pos_tol, double rot_tol,
                       double speed_tol) {
  const double speed = speedAgainstTarget(in);
  return heldObjectPositionError(in.tcp_pose, in.target_pose, object) <= pos_tol &&
         heldObjectRotationError(in.tcp_pose, in.target_pose, object) <= rot_tol && speed <= speed_tol;
}

}  // namespace handover::fsm
