// Grasp selection: the side grasp of the issue is reachable away from every
// limit, larger joint margins win, and hysteresis holds the choice under
// small perturbations but not under large ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "control/grasp/chain_kinematics.hpp"
#include "control/grasp/grasp_selector.hpp"
#include "control/grasp/shape_grasps.hpp"
#include "tests/control/grasp/panda_fixture.hpp"
#include "tests/support/units.hpp"

namespace handover::control::grasp {
namespace {

using handover::test::kDeg;

using testing::tcpPose;

double rotationAngle(const Matrix3& a, const Matrix3& b) { return Eigen::AngleAxisd(a * b.transpose()).angle(); }

// issue 12's first case: an upright bottle in front of the robot, taken from the side
GraspSpec bottleSideGrasp() {
  GraspSpec s;
  s.placement.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  s.has_free_axis = true;
  s.free_axis = Vector3::UnitZ();
  return s;
}

Isometry bottleAt(const Vector3& p) {
  Isometry X = Isometry::Identity();
  X.translation() = p;
  return X;
}

// Every candidate the selection holds feasible keeps what the constraints keep
// from `body`, at its grasp (`at_pre_grasp` false) or its pre-grasp
// configuration: every capsule at least its keep from it. Returns how many.
int feasibleClearOf(const Model& model, const GraspSelector& selector, const ObstacleCapsule& body, bool at_pre_grasp) {
  ObstacleCapsule bare = body;
  bare.keep_arm = bare.keep_gripper = 0.0;
  ChainPoses poses;
  int feasible = 0;
  for (const CandidateEvaluation& e : selector.evaluations()) {
    if (!e.feasible) continue;
    ++feasible;
    chainPoses(model, at_pre_grasp ? e.q_pre_grasp : e.q_grasp, poses);
    EXPECT_GE(personBodyClearance(model, poses, &body, 1), 0.0);
    EXPECT_GE(personBodyClearance(model, poses, &bare, 1), std::min(body.keep_arm, body.keep_gripper) - 1e-12);
  }
  return feasible;
}

TEST(GraspSelector, SideGraspOfAnUprightBottleStaysAwayFromEveryLimit) {
  const Model& model = testing::panda();
  GraspSelector selector(model, {bottleSideGrasp()}, testing::shippedConfig());
  const Isometry X_obj = bottleAt(Vector3(0.55, 0.0, 0.30));
  const GraspChoice& c = selector.update(X_obj, testing::readyConfiguration());
  ASSERT_TRUE(c.valid);
  EXPECT_GE(smallestLimitDistance(model, c.q_grasp), 0.2);
  EXPECT_GE(smallestLimitDistance(model, c.q_pre_grasp), 0.2);
  // the configurations reach the frames they claim
  const Isometry X_g = tcpPose(model, c.q_grasp), X_p = tcpPose(model, c.q_pre_grasp);
  EXPECT_LT((X_g.translation() - c.grasp.translation()).norm(), 1e-3);
  EXPECT_LT(rotationAngle(X_g.linear(), c.grasp.linear()), 0.5 * kDeg);
  EXPECT_LT((X_p.translation() - c.pre_grasp.translation()).norm(), 1e-3);
  EXPECT_LT(rotationAngle(X_p.linear(), c.pre_grasp.linear()), 0.5 * kDeg);
  // it is one of the admissible grasps: horizontal approach, fingers across the axis
  EXPECT_NEAR(c.grasp.linear().col(2).z(), 0.0, 1e-9);
  EXPECT_NEAR(c.grasp.linear().col(1).z(), 0.0, 1e-9);
  // the best is no worse than any other reachable candidate (hysteresis is moot on the first update)
  for (const CandidateEvaluation& e : selector.evaluations()) {
    if (e.feasible) {
      EXPECT_LE(e.score.total, c.score.total + 1e-12);
    }
  }
}

TEST(GraspSelector, SideAndFortyFiveDegreeGraspsOverTheHandoverRegion) {
  // where people offer objects: 0.4-0.7 m in front, 0.5 m wide, 0.2-0.4 m above the table
  const Model& model = testing::panda();
  for (double elevation : {0.0, M_PI / 4}) {
    GraspSpec s = bottleSideGrasp();
    s.placement.linear() = Eigen::AngleAxisd(M_PI / 2 + elevation, Vector3::UnitY()).toRotationMatrix();
    GraspSelector selector(model, {s}, testing::shippedConfig());
    for (double x : {0.4, 0.55, 0.7})
      for (double y : {-0.25, 0.0, 0.25})
        for (double z : {0.2, 0.4}) {
          selector.reset();
          const GraspChoice& c = selector.update(bottleAt(Vector3(x, y, z)), testing::readyConfiguration());
          ASSERT_TRUE(c.valid) << x << " " << y << " " << z;
          EXPECT_GE(smallestLimitDistance(model, c.q_grasp), 0.2) << x << " " << y << " " << z;
          EXPECT_GE(smallestLimitDistance(model, c.q_pre_grasp), 0.2) << x << " " << y << " " << z;
        }
  }
}

TEST(GraspSelector, FortyFiveDegreeGraspOfABottleIsReachable) {
  const Model& model = testing::panda();
  GraspSpec s = bottleSideGrasp();
  s.placement.linear() = Eigen::AngleAxisd(3 * M_PI / 4, Vector3::UnitY()).toRotationMatrix();  // 45 deg from above
  GraspSelector selector(model, {s}, testing::shippedConfig());
  const GraspChoice& c = selector.update(bottleAt(Vector3(0.55, 0.0, 0.30)), testing::readyConfiguration());
  ASSERT_TRUE(c.valid);
  EXPECT_NEAR(c.grasp.linear().col(2).z(), -std::sqrt(0.5), 1e-9);
  EXPECT_GE(smallestLimitDistance(model, c.q_grasp), 0.2);
  EXPECT_GE(smallestLimitDistance(model, c.q_pre_grasp), 0.2);
}

TEST(GraspSelector, LongObjectPointingAtTheRobotIsNotTakenFromBelowTheTable) {
  // issue 12: a long object carried horizontally, pointing at the robot, low
  // over the table; the grasp closes across its axis from any side around it
  const Model& model = testing::panda();
  GraspSpec across;
  across.placement.linear() = Eigen::AngleAxisd(-M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  across.has_free_axis = true;
  Isometry X_obj = Isometry::Identity();
  X_obj.linear() = Eigen::AngleAxisd(-M_PI / 2, Vector3::UnitY()).toRotationMatrix();  // object z along world -x
  X_obj.translation() = Vector3(0.5, 0.0, 0.20);  // low enough that the hand would reach into the table from below
  GraspSelector selector(model, {across}, testing::shippedConfig());
  const GraspChoice& c = selector.update(X_obj, testing::readyConfiguration());
  ASSERT_TRUE(c.valid);
  EXPECT_LT(c.grasp.linear().col(2).z(), 0.5);  // not coming up from below
  EXPECT_GE(smallestLimitDistance(model, c.q_grasp), 0.2);
  // every candidate that comes from below is out: its hand would be in the table
  int from_below = 0;
  for (const CandidateEvaluation& e : selector.evaluations()) {
    if (e.grasp.linear().col(2).z() > 0.9) {
      ++from_below;
      EXPECT_FALSE(e.feasible);
    }
  }
  EXPECT_GT(from_below, 0);
  // and the arm of the chosen configurations stays above it
  ChainPoses poses;
  chainPoses(model, c.q_grasp, poses);
  EXPECT_GE(lowestArmPoint(model, poses), testing::shippedConfig().table_clearance);
  chainPoses(model, c.q_pre_grasp, poses);
  EXPECT_GE(lowestArmPoint(model, poses), testing::shippedConfig().table_clearance);
}

TEST(GraspSelector, PrefersTheCandidateWithLargerJointMargins) {
  // two declared grasps, both reachable: A only with the elbow folded to
  // 0.12 rad from its limit (the elbow angle follows from the shoulder-wrist
  // distance, so no redundancy helps), B at the ready pose. The arm sits at A,
  // so motion favours A; the joint margin must still win.
  const Model& model = testing::panda();
  Vector7 q_a = testing::readyConfiguration();
  q_a[3] = model.q_min[3] + 0.12;
  GraspSpec a, b;
  a.placement = tcpPose(model, q_a);  // object frame = world
  b.placement = tcpPose(model, testing::readyConfiguration());
  GraspSelectionConfig cfg = testing::shippedConfig();
  cfg.candidates.parallel_gripper_twin = false;
  GraspSelector selector(model, {a, b}, cfg);
  const GraspChoice& c = selector.update(Isometry::Identity(), q_a);
  ASSERT_TRUE(c.valid);
  const CandidateEvaluation& ea = selector.evaluations()[0];
  ASSERT_TRUE(ea.feasible);  // a real choice
  EXPECT_LT(smallestLimitDistance(model, ea.q_grasp), 0.25);  // the premise: A stays folded
  EXPECT_EQ(c.index, 1);
  EXPECT_GT(c.score.joint_margin, ea.score.joint_margin);
  EXPECT_LT(ea.score.motion, c.score.motion);
}

// turns the object about the approach axis of `grasp` (world) through the grasp point
Isometry turnedAboutApproach(const Isometry& grasp, double angle) {
  const Vector3 p = grasp.translation();
  return Eigen::Translation3d(p) * Eigen::AngleAxisd(angle, grasp.linear().col(2)) * Eigen::Translation3d(-p);
}

// A top grasp at the ready pose's TCP (and its twin), selected with the shipped config.
GraspSpec topGraspAtReady() {
  GraspSpec top;
  top.placement = tcpPose(testing::panda(), testing::readyConfiguration());
  return top;
}

TEST(GraspSelector, HysteresisHoldsUnderSmallPerturbationsAndSwitchesUnderLargeOnes) {
  // a top grasp and its twin; the object turns about the approach axis, which
  // turns the wrist (joint 7) of both. At a quarter turn both need the same
  // wrist motion from the ready pose: their scores cross there.
  const Model& model = testing::panda();
  const GraspSpec top = topGraspAtReady();
  GraspSelector selector(model, {top}, testing::shippedConfig());
  const Vector7 q_now = testing::readyConfiguration();
  const GraspChoice& first = selector.update(Isometry::Identity(), q_now);
  ASSERT_TRUE(first.valid);
  const int chosen = first.index;
  EXPECT_FALSE(selector.candidates()[chosen].twin);  // no motion needed: the obvious one
  const int other = 1 - chosen;

  // the object turns slowly toward the crossing
  for (double angle = 0.0; angle < M_PI / 2 - 0.06; angle += 0.05) {
    ASSERT_EQ(selector.update(turnedAboutApproach(top.placement, angle), q_now).index, chosen);
  }
  // then jitters across it (sensor noise, 5 mm and 3 degrees)
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int other_ahead = 0;
  for (int k = 0; k < 40; ++k) {
    Isometry X_obj = turnedAboutApproach(top.placement, M_PI / 2 + 0.05 * u(rng));
    X_obj.translation() += 0.005 * Vector3(u(rng), u(rng), u(rng));
    const GraspChoice& c = selector.update(X_obj, q_now);
    ASSERT_TRUE(c.valid);
    EXPECT_EQ(c.index, chosen) << "update " << k;
    EXPECT_FALSE(c.switched);
    if (selector.evaluations()[other].score.total > selector.evaluations()[chosen].score.total) ++other_ahead;
  }
  // the premise: without hysteresis the choice would have flickered
  EXPECT_GT(other_ahead, 0);
  EXPECT_LT(other_ahead, 40);

  // a large turn takes the chosen grasp's wrist toward its limit: the twin wins
  const GraspChoice& c = selector.update(turnedAboutApproach(top.placement, 2.3), q_now);
  ASSERT_TRUE(c.valid);
  EXPECT_EQ(c.index, other);
  EXPECT_TRUE(c.switched);
  EXPECT_GT(smallestLimitDistance(model, c.q_grasp), 0.4);
}

TEST(GraspSelector, AHeldChoiceStaysWhileReachable) {
  // the same top grasp and twin: the large turn that made the twin win above
  // leaves the held choice in place (it is still reachable)
  const GraspSpec top = topGraspAtReady();
  GraspSelector selector(testing::panda(), {top}, testing::shippedConfig());
  const Vector7 q_now = testing::readyConfiguration();
  const int chosen = selector.update(Isometry::Identity(), q_now).index;
  ASSERT_GE(chosen, 0);
  selector.holdChoice(true);
  const GraspChoice& held = selector.update(turnedAboutApproach(top.placement, 2.3), q_now);
  ASSERT_TRUE(held.valid);
  EXPECT_EQ(held.index, chosen);
  EXPECT_FALSE(held.switched);
  EXPECT_GT(selector.evaluations()[1 - chosen].score.total, selector.evaluations()[chosen].score.total);
  // released: the better one wins again
  selector.holdChoice(false);
  EXPECT_EQ(selector.update(turnedAboutApproach(top.placement, 2.3), q_now).index, 1 - chosen);
}

// A give's presentation (a top grasp free to turn about the vertical, no
// twins): the turn the arm reaches best closes the fingers along the
// direction the receiver will pull; with the pull known the chosen turn
// closes them across it, so the object slides out between the pads.
TEST(GraspSelector, APresentationClosesTheFingersAcrossTheReceiversPull) {
  const Model& model = testing::panda();
  GraspSpec top = topGraspAtReady();
  top.has_free_axis = true;
  top.free_axis = Vector3::UnitZ();
  GraspSelectionConfig cfg = testing::shippedConfig();
  cfg.candidates.parallel_gripper_twin = false;
  const Vector7 q_now = testing::readyConfiguration();
  const Isometry X_hand = Isometry::Identity();  // the placement is the world TCP pose
  const Vector3 pull = top.placement.linear().col(1);  // along the closing axis of the ready pose
  ASSERT_NEAR(pull.z(), 0.0, 1e-6);  // the premise: a horizontal pull

  GraspSelector blind(model, {top}, cfg);
  const GraspChoice& first = blind.update(X_hand, q_now);
  ASSERT_TRUE(first.valid);
  EXPECT_GT(exitBlock(first.grasp, pull), 0.95) << "the premise: without the pull the ready turn wins";
  EXPECT_EQ(first.score.exit, 0.0);

  GraspSelector told(model, {top}, cfg);
  told.setPullDirection(pull);
  const GraspChoice& c = told.update(X_hand, q_now);
  ASSERT_TRUE(c.valid);
  EXPECT_LT(exitBlock(c.grasp, pull), 0.05);  // a quarter turn: the candidates step 30 degrees
  EXPECT_NEAR(c.score.exit, exitBlock(c.grasp, pull), 1e-12);
  EXPECT_GT(smallestLimitDistance(model, c.q_grasp), 0.3);
}

// A side presentation turns about the vertical by swinging its approach
// around the object: the pull does not count there (seed 317: weighed in
// full, 21 side gives swung the gripper into the receiver's reach and timed
// out), and the choice is the one the arm reaches best.
TEST(GraspSelector, ASidePresentationIsNotSwungAroundTheObjectForThePull) {
  const Model& model = testing::panda();
  GraspSelectionConfig cfg = testing::shippedConfig();
  cfg.candidates.parallel_gripper_twin = false;
  const Vector7 q_now = testing::readyConfiguration();
  const Isometry X_obj = bottleAt(Vector3(0.55, 0.0, 0.30));
  GraspSelector blind(model, {bottleSideGrasp()}, cfg);
  const GraspChoice& first = blind.update(X_obj, q_now);
  ASSERT_TRUE(first.valid);
  const Vector3 pull = first.grasp.linear().col(1);  // along its closing axis
  ASSERT_NEAR(pull.z(), 0.0, 1e-6);
  GraspSelector told(model, {bottleSideGrasp()}, cfg);
  told.setPullDirection(pull);
  const GraspChoice& c = told.update(X_obj, q_now);
  ASSERT_TRUE(c.valid);
  EXPECT_EQ(c.index, first.index);
  EXPECT_NEAR(c.score.exit, 0.0, 1e-9);
}

TEST(GraspSelector, AvoidsAnObstacleNearTheBestGraspConfiguration) {
  const Model& model = testing::panda();
  GraspSelector selector(model, {bottleSideGrasp()}, testing::shippedConfig());
  const Isometry X_obj = bottleAt(Vector3(0.55, 0.0, 0.30));
  const Vector7 q_now = testing::readyConfiguration();
  const GraspChoice free_choice = selector.update(X_obj, q_now);
  ASSERT_TRUE(free_choice.valid);
  // a forearm-sized capsule 5 cm above the elbow (joint 4, body 4) of that configuration
  ChainPoses poses;
  chainPoses(model, free_choice.q_grasp, poses);
  const Vector3 elbow = poses.oMb[4].translation();
  ObstacleCapsule forearm{elbow + Vector3(-0.1, 0.0, 0.1), elbow + Vector3(0.1, 0.0, 0.1), 0.04};
  selector.reset();
  const GraspChoice& c = selector.update(X_obj, q_now, &forearm, 1);
  ASSERT_TRUE(c.valid);
  chainPoses(model, c.q_grasp, poses);
  const double d_new = armClearance(model, poses, &forearm, 1);
  chainPoses(model, free_choice.q_grasp, poses);
  const double d_old = armClearance(model, poses, &forearm, 1);
  EXPECT_GT(d_new, d_old + 0.02);
  EXPECT_GT(c.score.total, totalScore(free_choice.score, testing::shippedConfig().score) - 1.0);
}

// a ball resting on a palm held out palm up, declared to be taken from the side: every side
// grasp puts the gripper's palm into the person's hand under the ball, so the selection takes
// it with a grasp that keeps the palm out of the hand (from above), however much the
// declared grasp is preferred
TEST(GraspSelector, ABallOnAPalmIsNotTakenWithTheGrippersPalmInTheHand) {
  const Model& model = testing::panda();
  std::vector<GraspSpec> specs = shapeGraspSpecs(PrimitiveShape::kSphere, {0.0255});
  ASSERT_EQ(specs.size(), 3u);
  GraspSpec side = bottleSideGrasp();
  side.preference = 10.0;  // declared, and preferred beyond any score difference
  specs.push_back(side);
  GraspSelector selector(model, specs, testing::shippedConfig());
  const Isometry X_obj = bottleAt(Vector3(0.55, 0.0, 0.30));
  ObstacleCapsule hand{X_obj.translation() - Vector3(0, 0, 0.04), X_obj.translation() - Vector3(0, 0, 0.04), 0.045};
  const GraspChoice& free_choice = selector.update(X_obj, testing::readyConfiguration());
  ASSERT_TRUE(free_choice.valid);
  EXPECT_NEAR(free_choice.grasp.linear().col(2).z(), 0.0, 1e-9);  // without the hand: the declared side grasp
  hand.gripper_works_here = true;
  selector.reset();
  const GraspChoice& c = selector.update(X_obj, testing::readyConfiguration(), &hand, 1);
  ASSERT_TRUE(c.valid);
  EXPECT_LT(c.grasp.linear().col(2).z(), -0.5);  // approaching from above
  ChainPoses poses;
  chainPoses(model, c.q_grasp, poses);
  EXPECT_GE(workZoneClearance(model, poses, &hand, 1), 0.0);
  for (const CandidateEvaluation& e : selector.evaluations()) {
    if (!e.feasible) continue;
    chainPoses(model, e.q_grasp, poses);
    EXPECT_GE(workZoneClearance(model, poses, &hand, 1), 0.0);
  }
}

// A ball in front of the robot, and the grasp the selection takes with nothing in the way.
struct BallBeforeTheRobot {
  const Model& model = testing::panda();
  GraspSelector selector{model, shapeGraspSpecs(PrimitiveShape::kSphere, {0.0255}), testing::shippedConfig()};
  Isometry X_obj = bottleAt(Vector3(0.55, 0.0, 0.30));
  GraspChoice free_choice = selector.update(X_obj, testing::readyConfiguration());
  /// A fresh selection with `body` in the way: it takes another grasp, and every feasible one keeps
  /// clear of `body` at its grasp (`at_pre_grasp` false) or its pre-grasp configuration.
  void expectAnotherGraspClearOf(const ObstacleCapsule& body, bool at_pre_grasp) {
    selector.reset();
    const GraspChoice& c = selector.update(X_obj, testing::readyConfiguration(), &body, 1);
    ASSERT_TRUE(c.valid);
    EXPECT_NE(c.index, free_choice.index);
    EXPECT_GT(feasibleClearOf(model, selector, body, at_pre_grasp), 0);
  }
};

// the person's forearm where the chosen grasp puts a finger: that grasp (and every other that
// would bring a capsule, the fingers' included, nearer the arm than the collision constraints
// let the robot go) is no grasp, and the selection takes another
TEST(GraspSelector, AGraspThatPutsAFingerOnThePersonsForearmIsNotTaken) {
  BallBeforeTheRobot ball;
  const Model& model = ball.model;
  ASSERT_TRUE(ball.free_choice.valid);
  // a forearm capsule through that grasp's fingertip capsule
  ChainPoses poses;
  chainPoses(model, ball.free_choice.q_grasp, poses);
  Vector3 tip = Vector3::Zero();
  bool found = false;
  for (const Capsule& c : model.capsules) {
    if (c.role != CapsuleRole::kFingertip) continue;
    tip = poses.oMb[c.body] * c.b;
    found = true;
  }
  ASSERT_TRUE(found);
  // the constraints keep the arm 4 cm from it, the gripper 5 mm
  ObstacleCapsule forearm{tip - Vector3(0, 0, 0.1), tip + Vector3(0, 0, 0.1), 0.02};
  forearm.keep_arm = 0.04;
  forearm.keep_gripper = 0.005;
  EXPECT_LT(personBodyClearance(model, poses, &forearm, 1), 0.0);
  ball.expectAnotherGraspClearOf(forearm, false);
}

// The arm passes the pre-grasp on its way in: a grasp whose pre-grasp
// configuration lies inside what the constraints keep from the person is not
// taken either (the arm stopped at the person's chest short of the pre-grasp
// for 10 s until the person let the ball fall, g727_00117).
TEST(GraspSelector, AGraspWhosePreGraspPutsTheArmIntoThePersonIsNotTaken) {
  BallBeforeTheRobot ball;
  const Model& model = ball.model;
  ASSERT_TRUE(ball.free_choice.valid);
  ChainPoses at_grasp, at_pre;
  chainPoses(model, ball.free_choice.q_grasp, at_grasp);
  chainPoses(model, ball.free_choice.q_pre_grasp, at_pre);
  // a small body behind the pre-grasp along the approach axis: within the arm's keep there,
  // clear of it at the grasp itself (the search below finds such a place)
  const Vector3 back = -ball.free_choice.pre_grasp.linear().col(2);
  ObstacleCapsule chest;
  chest.radius = 0.02;
  chest.keep_arm = 0.04;
  chest.keep_gripper = 0.005;
  bool placed = false;
  for (double s = 0.0; s < 0.4 && !placed; s += 0.005) {
    chest.a = chest.b = ball.free_choice.pre_grasp.translation() + s * back;
    placed = personBodyClearance(model, at_pre, &chest, 1) < 0.0 && personBodyClearance(model, at_grasp, &chest, 1) >= 0.0;
  }
  ASSERT_TRUE(placed) << "no point behind the pre-grasp is inside its keep and clear at the grasp";
  ball.expectAnotherGraspClearOf(chest, true);
}

// Reachability with hysteresis: an object carried outward to the edge of the
// workspace. A fresh selection refuses the grasp once its IK no longer
// converges (the arm stretched); the choice made before stays while its IK
// ends within keep_tolerance (the sensor's noise moved such a target in and
// out of reach and the choice flipped to a grasp a quarter turn away and
// back), and is given up beyond that.
TEST(GraspSelector, TheChosenGraspStaysReachableAcrossTheEdgeOfTheWorkspaceWithinTheKeepTolerance) {
  const Model& model = testing::panda();
  GraspSpec top;  // from above, fingers along y
  top.placement.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  const GraspSelectionConfig config = testing::shippedConfig();
  ASSERT_GT(config.keep_tolerance.position, 10.0 * config.ik.position_tolerance);
  const Vector7 q_now = testing::readyConfiguration();
  const auto freshlyReachable = [&](double x) {
    GraspSelector fresh(model, {top}, config);
    return fresh.update(bottleAt(Vector3(x, 0.0, 0.3)), q_now).valid;
  };
  // the edge along x, to 0.1 mm
  double in = 0.55, out = 1.2;
  ASSERT_TRUE(freshlyReachable(in));
  ASSERT_FALSE(freshlyReachable(out));
  while (out - in > 1e-4) {
    const double mid = 0.5 * (in + out);
    (freshlyReachable(mid) ? in : out) = mid;
  }
  const double beyond = out + 0.001;  // 1 mm past the edge
  ASSERT_FALSE(freshlyReachable(beyond));

  // the object carried there in 1 cm steps, then 1 mm at a time
  GraspSelector selector(model, {top}, config);
  Vector7 q = q_now;
  double x = in - 0.1;
  for (; x < in - 0.005; x += 0.01) {
    const GraspChoice& c = selector.update(bottleAt(Vector3(x, 0.0, 0.3)), q);
    ASSERT_TRUE(c.valid) << "x = " << x;
    q = c.q_grasp;  // the arm follows its choice
  }
  const int chosen = selector.choice().index;
  for (; x <= beyond; x += 0.001) {
    const GraspChoice& c = selector.update(bottleAt(Vector3(x, 0.0, 0.3)), q);
    ASSERT_TRUE(c.valid) << "x = " << x << " (the edge at " << out << ")";
    EXPECT_EQ(c.index, chosen);
    EXPECT_FALSE(c.switched);
  }
  // what it keeps still reaches the object to within the keep tolerance
  const Isometry X_g = tcpPose(model, selector.choice().q_grasp);
  EXPECT_LT((X_g.translation() - selector.choice().grasp.translation()).norm(), config.keep_tolerance.position);
  // far beyond the tolerance it is given up
  EXPECT_FALSE(selector.update(bottleAt(Vector3(out + 0.03, 0.0, 0.3)), q).valid);
}

// A body beside the outer fingertip of configuration `q` on the side of `grasp`'s closing axis, placed
// (bisected along that axis) where personBodyClearance(sharing) is `clearance` (m).
ObstacleCapsule bodyBesideTheFingertips(const Model& model, const Vector7& q, const Isometry& grasp, ObstacleCapsule body,
                                        double clearance, bool sharing) {
  ChainPoses poses;
  chainPoses(model, q, poses);
  const Vector3 side = grasp.linear().col(1);
  Vector3 tip = grasp.translation();
  for (const Capsule& c : model.capsules) {
    if (c.role != CapsuleRole::kFingertip) continue;
    const Vector3 p = poses.oMb[c.body] * c.b;
    if (p.dot(side) > tip.dot(side)) tip = p;
  }
  double near = 0.0, far = 0.3;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (near + far);
    body.a = body.b = tip + mid * side;
    (personBodyClearance(model, poses, &body, 1, sharing) < clearance ? near : far) = mid;
  }
  body.a = body.b = tip + far * side;
  return body;
}

// Feasibility with hysteresis, as reachability: the choice stays while its configuration comes
// nearer a body than the constraints keep by less than keep_tolerance.position; a fresh selection
// does not take it there, and beyond the tolerance it is given up. A grasp at the edge of a keep
// crossed it back and forth with the sensor's 1-2 mm of noise, and the target jumped between two
// grasps 10 cm apart every 0.1-0.3 s for 10 s (g1101_00584).
TEST(GraspSelector, TheChosenGraspStaysWhileItsConfigurationIsWithinTheKeepToleranceOfABodysKeep) {
  const Model& model = testing::panda();
  GraspSpec top;  // from above, fingers along y
  top.placement.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  const GraspSelectionConfig config = testing::shippedConfig();
  const double band = config.keep_tolerance.position;
  ASSERT_GT(band, 0.002);
  const Isometry X_obj = bottleAt(Vector3(0.55, 0.0, 0.3));
  GraspSelector selector(model, {top}, config);
  const GraspChoice first = selector.update(X_obj, testing::readyConfiguration());
  ASSERT_TRUE(first.valid);
  const int chosen = first.index;
  const Vector7 q = first.q_grasp;
  // a body beside the grasp configuration's fingertips, `inside` m within the gripper's keep from it
  ChainPoses poses;
  chainPoses(model, q, poses);
  ObstacleCapsule proto;
  proto.radius = 0.02;
  proto.keep_arm = 0.04;
  proto.keep_gripper = 0.005;
  const auto bodyInside = [&](double inside) {
    return bodyBesideTheFingertips(model, q, first.grasp, proto, -inside, false);
  };
  const ObstacleCapsule just_inside = bodyInside(0.4 * band);
  ASSERT_NEAR(personBodyClearance(model, poses, &just_inside, 1), -0.4 * band, 1e-4);
  // a fresh selection does not take that grasp there
  GraspSelector fresh(model, {top}, config);
  const GraspChoice& f = fresh.update(X_obj, testing::readyConfiguration(), &just_inside, 1);
  EXPECT_TRUE(!f.valid || f.index != chosen);
  // the choice made before stays, again and again
  for (int k = 0; k < 5; ++k) {
    const GraspChoice& c = selector.update(X_obj, q, &just_inside, 1);
    ASSERT_TRUE(c.valid) << "update " << k;
    EXPECT_EQ(c.index, chosen) << "update " << k;
  }
  // beyond the tolerance it is given up
  const ObstacleCapsule well_inside = bodyInside(3.0 * band);
  const GraspChoice& c = selector.update(X_obj, q, &well_inside, 1);
  EXPECT_TRUE(!c.valid || c.index != chosen);
}

// The grasp itself is where the fingers share the object with the person's hand: there the
// constraints keep the gripper only the sharing rules' distance from the arm that holds it (no
// sensing budget), and the selection measures it against that. The pre-grasp, on the way in, is
// measured against what the approach keeps. Against the approach's keeps at the grasp too, balls
// and boxes held low had no grasp left at all (g1109_00061: the forearm 1.15 cm inside them).
TEST(GraspSelector, TheGraspIsJudgedOnTheSharingKeepsAndThePreGraspOnTheApproachs) {
  const Model& model = testing::panda();
  GraspSpec top;  // from above, fingers along y
  top.placement.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  const GraspSelectionConfig config = testing::shippedConfig();
  const Isometry X_obj = bottleAt(Vector3(0.55, 0.0, 0.3));
  GraspSelector free(model, {top}, config);
  const GraspChoice first = free.update(X_obj, testing::readyConfiguration());
  ASSERT_TRUE(first.valid);
  ObstacleCapsule forearm;
  forearm.radius = 0.035;
  forearm.keep_arm = forearm.keep_arm_sharing = 0.04;
  forearm.keep_gripper = 0.021;          // apart: sDist and the sensing budget
  forearm.keep_gripper_sharing = 0.005;  // sharing: sDist alone
  // 1 cm inside the approach's keep at the grasp, 0.6 cm beyond the sharing keep
  const ObstacleCapsule body = bodyBesideTheFingertips(model, first.q_grasp, first.grasp, forearm, -0.01, false);
  {
    ChainPoses poses;
    chainPoses(model, first.q_grasp, poses);
    ASSERT_NEAR(personBodyClearance(model, poses, &body, 1), -0.01, 1e-4);
    ASSERT_NEAR(personBodyClearance(model, poses, &body, 1, true), 0.006, 1e-4);
    chainPoses(model, first.q_pre_grasp, poses);
    ASSERT_GT(personBodyClearance(model, poses, &body, 1), 0.0);  // the pre-grasp is clear of it
  }
  GraspSelector sharing(model, {top}, config);
  const GraspChoice& c = sharing.update(X_obj, testing::readyConfiguration(), &body, 1);
  ASSERT_TRUE(c.valid);
  EXPECT_TRUE(sharing.evaluations()[static_cast<std::size_t>(first.index)].feasible);
  // the same body without sharing keeps (the approach's everywhere): that grasp is refused
  ObstacleCapsule apart_only = body;
  apart_only.keep_arm_sharing = apart_only.keep_gripper_sharing = -1.0;
  GraspSelector apart(model, {top}, config);
  apart.update(X_obj, testing::readyConfiguration(), &apart_only, 1);
  EXPECT_FALSE(apart.evaluations()[static_cast<std::size_t>(first.index)].feasible);
  // and the pre-grasp keeps the approach's: that body as near the pre-grasp's fingertips is refused
  const ObstacleCapsule at_pre =
      bodyBesideTheFingertips(model, first.q_pre_grasp, first.pre_grasp, forearm, -0.01, false);
  GraspSelector pre(model, {top}, config);
  pre.update(X_obj, testing::readyConfiguration(), &at_pre, 1);
  EXPECT_FALSE(pre.evaluations()[static_cast<std::size_t>(first.index)].feasible);
}

TEST(GraspSelector, ReportsNoChoiceForAnObjectOutOfReach) {
  const Model& model = testing::panda();
  GraspSelector selector(model, {bottleSideGrasp()}, testing::shippedConfig());
  const GraspChoice& c = selector.update(bottleAt(Vector3(1.5, 0.0, 0.3)), testing::readyConfiguration());
  EXPECT_FALSE(c.valid);
  for (const CandidateEvaluation& e : selector.evaluations()) EXPECT_FALSE(e.feasible);
}

TEST(GraspSelector, NonFiniteInputKeepsTheChoice) {
  const Model& model = testing::panda();
  GraspSelector selector(model, {bottleSideGrasp()}, testing::shippedConfig());
  const GraspChoice before = selector.update(bottleAt(Vector3(0.55, 0.0, 0.30)), testing::readyConfiguration());
  ASSERT_TRUE(before.valid);
  // the choice names its candidate in the object frame
  EXPECT_LT((before.grasp_in_object.matrix() - selector.candidates()[before.index].in_object.matrix()).norm(), 1e-15);
  Isometry bad = bottleAt(Vector3(0.55, 0.0, 0.30));
  bad.translation().x() = std::numeric_limits<double>::quiet_NaN();
  const GraspChoice& c = selector.update(bad, testing::readyConfiguration());
  EXPECT_TRUE(c.valid);
  EXPECT_EQ(c.index, before.index);
  EXPECT_FALSE(c.switched);
  EXPECT_TRUE(c.q_grasp.allFinite());
  Vector7 q_bad = testing::readyConfiguration();
  q_bad[2] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(selector.update(bottleAt(Vector3(0.55, 0.0, 0.30)), q_bad).index, before.index);
}

TEST(GraspSelector, WarmUpdatesTrackAMovingObject) {
  const Model& model = testing::panda();
  GraspSelector selector(model, {bottleSideGrasp()}, testing::shippedConfig());
  Vector7 q_now = testing::readyConfiguration();
  int cold_iterations = 0, warm_iterations = 0;
  for (int k = 0; k < 60; ++k) {  // 1 s at 60 Hz, 0.15 m/s sideways
    const GraspChoice& c = selector.update(bottleAt(Vector3(0.55, -0.075 + 0.0025 * k, 0.30)), q_now);
    ASSERT_TRUE(c.valid) << k;
    int its = 0;
    for (const CandidateEvaluation& e : selector.evaluations()) its += e.iterations;
    (k == 0 ? cold_iterations : warm_iterations) += its;
    const Isometry X = tcpPose(model, c.q_grasp);
    EXPECT_LT((X.translation() - c.grasp.translation()).norm(), 1e-3);
  }
  // warm starts are what makes the sensor rate affordable
  EXPECT_LT(warm_iterations / 59.0, 0.25 * cold_iterations);
}

TEST(GraspSelector, AWarmCandidateFollowsTheArmOntoAnotherIkBranch) {
  // A give's presentation (g1_00122): the plan was found while the arm stood
  // one way; the arm then waited in another configuration from which the
  // same grasp is a short move. Solved only from its previous solution, the
  // candidate kept the first one and asked the approach for a 3.9 rad turn of
  // the wrist, which it never made. Here: one grasp pose, two of its IK
  // solutions far apart in joint space, the arm first at one, then at the other.
  const Model& model = testing::panda();
  const GraspSelectionConfig& config = testing::shippedConfig();
  const Vector7 q_first = (Vector7() << -0.24, -0.33, 0.02, -2.33, 0.89, 2.07, 2.24).finished();
  const Isometry target = tcpPose(model, q_first);
  Vector7 q_other = q_first;
  bool found = false;
  std::mt19937 rng(7);
  for (int k = 0; k < 500 && !found; ++k) {
    const IkResult r = solveIk(model, model.frameId(config.frame), target, testing::randomConfiguration(model, rng, 0.2), config.ik);
    if (r.converged && (r.q - q_first).norm() > 2.5 && smallestLimitDistance(model, r.q) > 0.5) {
      q_other = r.q;
      found = true;
    }
  }
  ASSERT_TRUE(found) << "no second IK solution for the test pose";

  GraspSpec at_tcp;  // the grasp frame is the object's frame
  GraspSelectionConfig no_twin = config;
  no_twin.candidates.parallel_gripper_twin = false;
  GraspSelector selector(model, {at_tcp}, no_twin);
  ASSERT_TRUE(selector.update(target, q_first).valid);
  EXPECT_LT((selector.choice().q_grasp - q_first).norm(), 0.3);
  // the arm is now at the other solution: the plan follows it there
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(selector.update(target, q_other).valid);
  EXPECT_LT((selector.choice().q_grasp - q_other).norm(), 0.3)
      << "still " << selector.choice().q_grasp.transpose() << ", the arm at " << q_other.transpose();
  const Isometry reached = tcpPose(model, selector.choice().q_grasp);
  EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-3);
  EXPECT_LT(rotationAngle(reached.linear(), target.linear()), 0.5 * kDeg);
}

}  // namespace
}  // namespace handover::control::grasp
