// The presentation test compares the held object as the receiver sees it:
// its position, and its orientation up to the symmetry of its shape.
#include <gtest/gtest.h>

#include <cmath>

#include "fsm/handover/perception_checks.hpp"
#include "fsm/handover/receiver_take.hpp"

namespace handover::fsm {
namespace {

constexpr double kDeg = M_PI / 180.0;

ObjectInfo objectOf(io::ObjectShape::Kind kind, const Isometry& grasp_in_object) {
  ObjectInfo o;
  o.shape.kind = kind;
  o.shape.size = Vector3(0.04, 0.12, 0.0);
  o.grasp_in_object = grasp_in_object;
  return o;
}

// A TCP pose turned by `angle` about `axis` (world) through `pivot`.
Isometry turned(const Isometry& tcp, const Vector3& pivot, const Vector3& axis, double angle) {
  const Isometry turn = Eigen::Translation3d(pivot) * Eigen::AngleAxisd(angle, axis.normalized()) *
                        Eigen::Translation3d(-pivot);
  return turn * tcp;
}

HandoverInput presenting(const Isometry& tcp, const Isometry& target) {
  HandoverInput in;
  in.tcp_pose = tcp;
  in.target_pose = target;
  return in;
}

const Isometry kTarget = Eigen::Translation3d(0.5, 0.1, 0.4) * Eigen::AngleAxisd(2.0, Vector3(1, 1, 0).normalized());

TEST(PresentedAtTarget, ABallTurnedAboutItsCentreIsPresented) {
  const ObjectInfo ball = objectOf(io::ObjectShape::Kind::kSphere, Isometry::Identity());
  const Isometry tcp = turned(kTarget, kTarget.translation(), Vector3(0.3, -1, 0.2), 40 * kDeg);
  EXPECT_NEAR(rotationError(tcp, kTarget), 40 * kDeg, 1e-9);  // the gripper is 40 deg off
  EXPECT_TRUE(presentedAtTarget(presenting(tcp, kTarget), ball, 0.01, 15 * kDeg, 0.05));
  // its centre is what counts: the same turn about a point beside it moves the ball
  const Isometry off = turned(kTarget, kTarget.translation() + Vector3(0.0, 0.0, 0.1), Vector3(0, 1, 0), 40 * kDeg);
  EXPECT_GT(heldObjectPositionError(off, kTarget, ball), 0.05);
  EXPECT_FALSE(presentedAtTarget(presenting(off, kTarget), ball, 0.01, 15 * kDeg, 0.05));
}

TEST(PresentedAtTarget, ACylinderCountsOnlyItsAxisEitherEndFirst) {
  // grasped 3 cm along its axis from its centre, the grasp turned about the axis
  const Isometry grasp = Eigen::Translation3d(0.0, 0.0, 0.03) * Eigen::AngleAxisd(0.7, Vector3::UnitZ()) *
                         Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY());
  const ObjectInfo can = objectOf(io::ObjectShape::Kind::kCylinder, grasp);
  const Isometry object_at_target = kTarget * grasp.inverse();
  const Vector3 axis = object_at_target.linear().col(2);
  const Vector3 centre = object_at_target.translation();
  // spun about its own axis: the same can for the receiver
  const Isometry spun = turned(kTarget, centre, axis, 50 * kDeg);
  EXPECT_NEAR(heldObjectRotationError(spun, kTarget, can), 0.0, 1e-9);
  EXPECT_NEAR(heldObjectPositionError(spun, kTarget, can), 0.0, 1e-9);
  EXPECT_TRUE(presentedAtTarget(presenting(spun, kTarget), can, 0.01, 15 * kDeg, 0.05));
  // upside down about its centre: its ends are alike
  const Vector3 across = axis.unitOrthogonal();
  EXPECT_NEAR(heldObjectRotationError(turned(kTarget, centre, across, M_PI), kTarget, can), 0.0, 1e-9);
  // its axis tilted by 30 deg: not presented
  const Isometry tilted = turned(kTarget, centre, across, 30 * kDeg);
  EXPECT_NEAR(heldObjectRotationError(tilted, kTarget, can), 30 * kDeg, 1e-9);
  EXPECT_FALSE(presentedAtTarget(presenting(tilted, kTarget), can, 0.01, 15 * kDeg, 0.05));
}

TEST(PresentedAtTarget, ABoxAndAnUnknownShapeCountTheWholeRotation) {
  for (const auto kind : {io::ObjectShape::Kind::kBox, io::ObjectShape::Kind::kUnknown}) {
    const ObjectInfo box = objectOf(kind, Eigen::Translation3d(0.0, 0.0, 0.02) * Isometry::Identity());
    const Isometry tcp = turned(kTarget, kTarget.translation(), Vector3::UnitZ(), 20 * kDeg);
    EXPECT_NEAR(heldObjectRotationError(tcp, kTarget, box), 20 * kDeg, 1e-9);
    EXPECT_FALSE(presentedAtTarget(presenting(tcp, kTarget), box, 0.05, 15 * kDeg, 0.05));
    EXPECT_TRUE(presentedAtTarget(presenting(tcp, kTarget), box, 0.05, 25 * kDeg, 0.05));
  }
}

TEST(PresentedAtTarget, AMovingGripperIsNotPresentedYet) {
  const ObjectInfo ball = objectOf(io::ObjectShape::Kind::kSphere, Isometry::Identity());
  HandoverInput in = presenting(kTarget, kTarget);
  in.tcp_velocity.head<3>() = Vector3(0.0, 0.1, 0.0);
  EXPECT_FALSE(presentedAtTarget(in, ball, 0.01, 15 * kDeg, 0.05));
  in.target_velocity.head<3>() = Vector3(0.0, 0.1, 0.0);  // moving with a moving hand is fine
  EXPECT_TRUE(presentedAtTarget(in, ball, 0.01, 15 * kDeg, 0.05));
}

// Withdrawal at the workspace's edge: entering the region offers, leaving it grown by the
// margin withdraws. A receiver's hand resting 5 mm inside the box's face went out and in with
// the sensor's noise: the give cycled Approach / Retreat until it aborted (g91_00389).
TEST(AlignedWhenClosed, TheTcpStillSlidingInIsJudgedWhereTheFingersMeetTheObject) {
  // 1.5 cm short along the approach axis, sliding in at 0.1 m/s: in 0.15 s it is there
  const Vector3 approach = kTarget.linear().col(2);
  Isometry tcp = kTarget;
  tcp.translation() -= 0.015 * approach;
  HandoverInput in = presenting(tcp, kTarget);
  in.tcp_velocity.head<3>() = 0.1 * approach;
  EXPECT_TRUE(alignedWhenClosed(in, 0.02, 10 * kDeg, 0.15));
  EXPECT_FALSE(alignedWithTarget(in, 0.02, 10 * kDeg, 0.05));  // the speed test waited for rest
  // the same speed across the fingers carries it 1.5 cm sideways as they close: not yet
  in.tcp_velocity.head<3>() = 0.1 * kTarget.linear().col(1);
  EXPECT_FALSE(alignedWhenClosed(in, 0.02, 10 * kDeg, 0.15));
  EXPECT_TRUE(alignedWhenClosed(in, 0.02, 10 * kDeg, 0.0));  // a close that is instant: where it is now
  // a target that moves with the TCP: nothing relative
  in.target_velocity.head<3>() = in.tcp_velocity.head<3>();
  EXPECT_TRUE(alignedWhenClosed(in, 0.02, 10 * kDeg, 0.15));
}

TEST(AlignedWhenClosed, AGripperStillTurningIsNotAligned) {
  HandoverInput in = presenting(turned(kTarget, kTarget.translation(), Vector3::UnitZ(), 5 * kDeg), kTarget);
  EXPECT_TRUE(alignedWhenClosed(in, 0.02, 10 * kDeg, 0.15));
  in.tcp_velocity.tail<3>() = Vector3(0.0, 0.0, 1.0);  // 1 rad/s: 8.6 deg more by then
  EXPECT_FALSE(alignedWhenClosed(in, 0.02, 10 * kDeg, 0.15));
  // and too far now stays too far, whatever the motion
  in = presenting(turned(kTarget, kTarget.translation(), Vector3::UnitZ(), 12 * kDeg), kTarget);
  EXPECT_FALSE(alignedWhenClosed(in, 0.02, 10 * kDeg, 0.0));
}

TEST(Withdrawn, AHandOnTheWorkspacesEdgeIsWithdrawnOnlyOnceOutsideTheMargin) {
  HandoverParams params;
  params.withdraw_workspace_margin = 0.05;
  HandoverContext ctx;
  ctx.params = &params;
  ctx.in.hand.valid = true;
  ctx.in.hand.age = 0.0;
  const double edge = params.workspace.box_min.y();
  for (const double beyond : {-0.005, 0.02, 0.045, 0.06}) {
    SCOPED_TRACE(beyond);
    ctx.in.hand.pose.translation() = Vector3(0.45, edge - beyond, 0.35);
    ASSERT_TRUE(params.workspace.contains(Vector3(0.45, 0.0, 0.35)));
    EXPECT_EQ(inWorkspace(ctx, true), beyond < 0.0) << "the offer's region has no margin";
    EXPECT_EQ(withdrawn(ctx, true), beyond > params.withdraw_workspace_margin);
  }
}

// A receiver takes hold of what the robot carries where their grip point
// meets its surface, wherever on the object that is: a book hanging 10 cm
// below the fingers is held by a hand at its lower edge, not by one beside
// the gripper 10 cm above it, nor by one 15 cm in front of it.
TEST(HandAtHeldObject, TheGripPointCountsAgainstTheObjectsSurfaceNotTheTcp) {
  HandoverParams params;
  HandoverContext ctx;
  ctx.params = &params;
  ctx.object.shape.kind = io::ObjectShape::Kind::kBox;
  ctx.object.shape.size = Vector3(0.14, 0.04, 0.20);
  // held 6 cm above its centre, the gripper coming along the object's x
  ctx.grasp.offset = Eigen::Translation3d(0.0, 0.0, 0.06) * Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY());
  ctx.in.tcp_pose = Eigen::Translation3d(0.45, 0.0, 0.40) * Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY());
  ctx.in.hand.valid = true;
  ctx.in.hand.age = 0.0;
  const Isometry object = ctx.in.tcp_pose * ctx.objectInTcp();
  ASSERT_LT((object.translation() - Vector3(0.45, 0.0, 0.34)).norm(), 1e-9);
  const auto at = [&](const Vector3& p) {
    ctx.in.hand.pose.translation() = p;
    return handAtHeldObject(ctx, 0.05);
  };
  EXPECT_TRUE(at(Vector3(0.45, 0.04, 0.26)));   // at its lower edge, beside it
  EXPECT_TRUE(at(Vector3(0.45, 0.0, 0.21)));    // 3 cm under it
  EXPECT_FALSE(at(Vector3(0.45, 0.0, 0.17)));   // 7 cm under it
  EXPECT_FALSE(at(Vector3(0.60, 0.0, 0.34)));   // 15 cm in front of its centre (8 cm off its face)
  ctx.in.hand.age = 1.0;                        // a hand not seen for a second holds nothing known
  EXPECT_FALSE(at(Vector3(0.45, 0.04, 0.26)));
}

}  // namespace
}  // namespace handover::fsm
