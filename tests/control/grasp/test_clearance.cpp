// Segment distances against a dense sampling, and the arm's clearance to an
// obstacle capsule against the distance from its posed capsules.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "control/grasp/clearance.hpp"
#include "control/grasp/grasp_score.hpp"
#include "tests/control/grasp/panda_fixture.hpp"

namespace handover::control::grasp {
namespace {

// brute force over a grid of both segments' parameters
double sampledDistance(const Vector3& p0, const Vector3& p1, const Vector3& q0, const Vector3& q1) {
  double best = std::numeric_limits<double>::infinity();
  const int n = 400;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      best = std::min(best, ((p0 + (p1 - p0) * i / n) - (q0 + (q1 - q0) * j / n)).norm());
  return best;
}

TEST(Clearance, SegmentDistanceMatchesSampling) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  auto point = [&] { return Vector3(u(rng), u(rng), u(rng)); };
  for (int k = 0; k < 30; ++k) {
    const Vector3 p0 = point(), p1 = point(), q0 = point(), q1 = point();
    EXPECT_NEAR(segmentDistance(p0, p1, q0, q1), sampledDistance(p0, p1, q0, q1), 3e-3);
    EXPECT_LE(segmentDistance(p0, p1, q0, q1), sampledDistance(p0, p1, q0, q1) + 1e-12);
  }
  // parallel, overlapping, degenerate and crossing cases
  EXPECT_NEAR(segmentDistance({0, 0, 0}, {1, 0, 0}, {0.5, 0.2, 0}, {1.5, 0.2, 0}), 0.2, 1e-12);
  EXPECT_NEAR(segmentDistance({0, 0, 0}, {1, 0, 0}, {2, 0.1, 0}, {3, 0.1, 0}), std::hypot(1.0, 0.1), 1e-12);
  EXPECT_NEAR(segmentDistance({0, 0, 0}, {0, 0, 0}, {1, -1, 0.3}, {1, 1, 0.3}), std::hypot(1.0, 0.3), 1e-12);
  EXPECT_NEAR(segmentDistance({-1, 0, 0}, {1, 0, 0}, {0, -1, 0.05}, {0, 1, 0.05}), 0.05, 1e-12);
}

TEST(Clearance, ArmClearanceIsTheNearestCapsuleSurface) {
  const Model& model = testing::panda();
  ChainPoses poses;
  chainPoses(model, testing::readyConfiguration(), poses);
  EXPECT_EQ(armClearance(model, poses, nullptr, 0), std::numeric_limits<double>::infinity());
  // a forearm-like capsule above the TCP, crossing the hand's x axis
  const Isometry tcp = chainFramePose(model, poses, model.frameId("tcp"));
  ObstacleCapsule o{tcp.translation() + Vector3(0.3, -0.2, 0.5), tcp.translation() + Vector3(0.3, 0.2, 0.5), 0.04};
  double expected = std::numeric_limits<double>::infinity();
  for (const Capsule& c : model.capsules) {
    const Vector3 a = poses.oMb[c.body] * c.a, b = poses.oMb[c.body] * c.b;
    expected = std::min(expected, sampledDistance(a, b, o.a, o.b) - c.radius - o.radius);
  }
  EXPECT_NEAR(armClearance(model, poses, &o, 1), expected, 3e-3);
  // and the score penalises it only inside clearance_ref
  ScoreWeights w;
  w.clearance_ref = expected + 0.1;
  ScoreTerms near = scoreConfiguration(model, model.frameId("tcp"), poses, testing::readyConfiguration(),
                                       testing::readyConfiguration(), &o, 1, w);
  EXPECT_GT(near.clearance, 0.0);
  w.clearance_ref = expected - 0.01;
  ScoreTerms far = scoreConfiguration(model, model.frameId("tcp"), poses, testing::readyConfiguration(),
                                      testing::readyConfiguration(), &o, 1, w);
  EXPECT_EQ(far.clearance, 0.0);
  EXPECT_GT(far.total, near.total);
}

// The arm at its ready pose (gripper pointing down) in `poses`, and a sphere of
// `radius` centred `depth` below its TCP.
ObstacleCapsule sphereBelowTheReadyTcp(double depth, double radius, ChainPoses& poses) {
  const Model& model = testing::panda();
  chainPoses(model, testing::readyConfiguration(), poses);
  const Vector3 at = chainFramePose(model, poses, model.frameId("tcp")).translation() - Vector3(0, 0, depth);
  return ObstacleCapsule{at, at, radius};
}

// the person's hand where the fingers work: the fingertip capsule closing
// around the object in it is not measured against it, the palm and the arm are
TEST(Clearance, TheHandWhereTheFingersWorkCountsOnlyAgainstThePalmAndTheArm) {
  const Model& model = testing::panda();
  ChainPoses poses;
  // a hand sphere 3 cm below the TCP (gripper pointing down): inside the fingertip capsule's
  // reach, clear of the palm
  ObstacleCapsule hand = sphereBelowTheReadyTcp(0.03, 0.02, poses);
  const Isometry tcp = chainFramePose(model, poses, model.frameId("tcp"));
  const double any = armClearance(model, poses, &hand, 1);
  EXPECT_LT(any, 0.0);  // the fingertip capsule overlaps it
  EXPECT_EQ(workZoneClearance(model, poses, &hand, 1), std::numeric_limits<double>::infinity());  // not a work zone
  hand.gripper_works_here = true;
  const double palm = workZoneClearance(model, poses, &hand, 1);
  EXPECT_GT(palm, 0.0);
  EXPECT_GT(armClearance(model, poses, &hand, 1), 0.0);
  double expected = std::numeric_limits<double>::infinity();
  for (const Capsule& c : model.capsules) {
    if (c.role == CapsuleRole::kFingertip) continue;
    const Vector3 a = poses.oMb[c.body] * c.a, b = poses.oMb[c.body] * c.b;
    expected = std::min(expected, sampledDistance(a, b, hand.a, hand.b) - c.radius - hand.radius);
  }
  EXPECT_NEAR(palm, expected, 3e-3);
  // moved up into the palm: a negative work-zone clearance
  hand.a = hand.b = tcp.translation() + Vector3(0, 0, 0.05);
  EXPECT_LT(workZoneClearance(model, poses, &hand, 1), 0.0);
}

TEST(Clearance, AHeldObjectCountsOnlyForTheHeldObjectClearanceAndThereTheFingertipsToo) {
  const Model& model = testing::panda();
  ChainPoses poses;
  // a ball 3 cm below the TCP (gripper pointing down): between the fingertips, clear of the palm
  ObstacleCapsule ball = sphereBelowTheReadyTcp(0.03, 0.02, poses);
  const Isometry tcp = chainFramePose(model, poses, model.frameId("tcp"));
  ball.held_object = true;
  ball.keep_arm = ball.keep_gripper = 0.005;
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(armClearance(model, poses, &ball, 1), inf);
  EXPECT_EQ(workZoneClearance(model, poses, &ball, 1), inf);
  EXPECT_EQ(personBodyClearance(model, poses, &ball, 1), inf);
  EXPECT_EQ(keepShortfall(model, poses, &ball, 1), 0.0);
  // every capsule counts, the fingertips too, beyond the keep
  ObstacleCapsule plain = ball;
  plain.held_object = false;
  const double overlap = armClearance(model, poses, &plain, 1);
  ASSERT_LT(overlap, 0.0);  // the fingertip capsule overlaps it
  EXPECT_NEAR(heldObjectClearance(model, poses, &ball, 1), overlap - 0.005, 1e-12);
  EXPECT_EQ(heldObjectClearance(model, poses, &plain, 1), inf);  // not a held object
  // 30 cm below the TCP: clear, by its distance less the keep
  ball.a = ball.b = plain.a = plain.b = tcp.translation() - Vector3(0, 0, 0.30);
  EXPECT_NEAR(heldObjectClearance(model, poses, &ball, 1), armClearance(model, poses, &plain, 1) - 0.005, 1e-12);
  EXPECT_GT(heldObjectClearance(model, poses, &ball, 1), 0.0);
}

// While the fingers share the object with the person's hand (a take's grasp) the constraints keep
// other distances (no sensing budget between the gripper and the arm that holds it): with `sharing`
// the clearance is measured beyond those keeps, and beyond the usual ones where none is given.
TEST(Clearance, WhileSharingTheClearanceIsBeyondTheSharingKeeps) {
  const Model& model = testing::panda();
  ChainPoses poses;
  ObstacleCapsule body = sphereBelowTheReadyTcp(0.20, 0.02, poses);  // clear of every capsule
  const double distance = armClearance(model, poses, &body, 1);
  ASSERT_GT(distance, 0.05);
  body.keep_arm = body.keep_gripper = 0.03;
  const double apart = personBodyClearance(model, poses, &body, 1);
  EXPECT_EQ(personBodyClearance(model, poses, &body, 1, true), apart);  // no sharing keeps: the same
  body.keep_arm_sharing = body.keep_gripper_sharing = 0.005;
  EXPECT_NEAR(personBodyClearance(model, poses, &body, 1, true), apart + 0.025, 1e-12);
  EXPECT_EQ(personBodyClearance(model, poses, &body, 1), apart);  // apart: the usual keeps still
  // the arm's and the gripper's each: only the gripper's comes nearer while sharing
  body.keep_arm_sharing = 0.03;
  const double sharing = personBodyClearance(model, poses, &body, 1, true);
  EXPECT_GE(sharing, apart);
  EXPECT_LE(sharing, apart + 0.025 + 1e-12);
}

// a box by a dense sampling of the segment, each point's distance exact (clamped to the box)
double sampledBoxDistance(const Vector3& p0, const Vector3& p1, const Vector3& centre, const Matrix3& axes,
                          const Vector3& half) {
  double best = std::numeric_limits<double>::infinity();
  const int n = 4000;
  for (int i = 0; i <= n; ++i) {
    const Vector3 p = axes.transpose() * (p0 + (p1 - p0) * i / n - centre);
    best = std::min(best, (p - p.cwiseMax(-half).cwiseMin(half)).norm());
  }
  return best;
}

TEST(Clearance, SegmentBoxDistanceMatchesSampling) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.3, 0.3), e(0.005, 0.08);
  auto point = [&] { return Vector3(u(rng), u(rng), u(rng)); };
  for (int k = 0; k < 60; ++k) {
    const Vector3 p0 = point(), p1 = point(), centre = point(), half(e(rng), e(rng), e(rng));
    const Matrix3 axes = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    const double d = segmentBoxDistance(p0, p1, centre, axes, half);
    EXPECT_NEAR(d, sampledBoxDistance(p0, p1, centre, axes, half), 2e-4) << "case " << k;
  }
  // through the box: 0; beside a face, parallel to it: the gap; past a corner: the corner's distance
  const Matrix3 I = Matrix3::Identity();
  const Vector3 half(0.045, 0.04, 0.015);
  EXPECT_EQ(segmentBoxDistance({-0.1, 0, 0}, {0.1, 0, 0}, Vector3::Zero(), I, half), 0.0);
  EXPECT_NEAR(segmentBoxDistance({-0.1, 0.01, 0.035}, {0.1, 0.01, 0.035}, Vector3::Zero(), I, half), 0.02, 1e-9);
  EXPECT_NEAR(segmentBoxDistance({0.145, 0.04, 0.015}, {0.3, 0.3, 0.3}, Vector3::Zero(), I, half), 0.1, 1e-9);
}

// the receiver's hand in a give (keep-only): measured against every capsule,
// the fingertips too, and only what comes nearer than its keep counts
TEST(Clearance, AKeepOnlyBoxCountsHowFarItsKeepHoldsTheArmShort) {
  const Model& model = testing::panda();
  ChainPoses poses;
  chainPoses(model, testing::readyConfiguration(), poses);
  const Isometry tcp = chainFramePose(model, poses, model.frameId("tcp"));
  // a palm-sized box whose top lies 3 cm under the TCP (gripper pointing down)
  ObstacleCapsule hand;
  hand.a = hand.b = tcp.translation() - Vector3(0, 0, 0.045);
  hand.box_half_extents = Vector3(0.045, 0.04, 0.015);
  hand.keep_only = true;
  hand.keep_gripper = 0.05;
  hand.keep_arm = 0.05;
  // the nearest capsule is the fingertips' (its lowest point: 2 cm around a segment 3.4 mm above the TCP)
  double nearest = std::numeric_limits<double>::infinity();
  for (const Capsule& c : model.capsules)
    nearest = std::min(nearest, sampledBoxDistance(poses.oMb[c.body] * c.a, poses.oMb[c.body] * c.b, hand.a,
                                                   Matrix3::Identity(), hand.box_half_extents) -
                                    c.radius);
  EXPECT_NEAR(nearest, 0.03 + 0.0034 - 0.02, 1e-3);
  EXPECT_NEAR(keepShortfall(model, poses, &hand, 1), 0.05 - nearest, 1e-4);
  hand.keep_gripper = hand.keep_arm = 0.005;
  EXPECT_EQ(keepShortfall(model, poses, &hand, 1), 0.0);  // kept: nothing short
  // keep-only: neither an obstacle to the clearance penalty nor a work zone
  EXPECT_EQ(armClearance(model, poses, &hand, 1), std::numeric_limits<double>::infinity());
  EXPECT_EQ(workZoneClearance(model, poses, &hand, 1), std::numeric_limits<double>::infinity());
  EXPECT_EQ(personBodyClearance(model, poses, &hand, 1), std::numeric_limits<double>::infinity());
  // and the score pays for the shortfall only
  hand.keep_gripper = 0.05;
  ScoreWeights w;
  const ScoreTerms t = scoreConfiguration(model, model.frameId("tcp"), poses, testing::readyConfiguration(),
                                          testing::readyConfiguration(), &hand, 1, w);
  EXPECT_NEAR(t.shortfall, std::min(1.0, std::pow((0.05 - nearest) / w.shortfall_ref, 2)), 1e-3);
  EXPECT_EQ(t.clearance, 0.0);
}

TEST(Scores, ManipulabilityVanishesAtTheStretchedSingularity) {
  const Model& model = testing::panda();
  ChainPoses poses;
  Matrix6x7 J;
  chainPoses(model, Vector7::Zero(), poses);  // arm straight up: a singular pose
  chainFrameJacobian(model, poses, model.frameId("tcp"), J);
  const double singular = manipulability(J);
  chainPoses(model, testing::readyConfiguration(), poses);
  chainFrameJacobian(model, poses, model.frameId("tcp"), J);
  const double ready = manipulability(J);
  EXPECT_LT(singular, 1e-6);
  EXPECT_GT(ready, 0.03);
  EXPECT_NEAR(ready, std::sqrt((J * J.transpose()).determinant()), 1e-9);
}

}  // namespace
}  // namespace handover::control::grasp
