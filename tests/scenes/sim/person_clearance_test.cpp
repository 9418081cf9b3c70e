// True robot-person clearance from MuJoCo's geometry (the judge's measure):
// far, then a known gap, then penetration of the hand, the torso and the head.
#include <gtest/gtest.h>

#include <cmath>

#include "scenes/scenario/body_dimensions.hpp"
#include "scenes/sim/simulation.hpp"
#include "sim_test_support.hpp"

namespace handover::sim {
namespace {

using test::personAway;

// steps once so that the geometry the clearance reads is the posed one
PersonClearance clearanceWith(Simulation& sim, const HumanBodyPoses& p) {
  EXPECT_TRUE(sim.setHumanPoses(p));
  test::holdStep(sim, test::readyPosture());
  return sim.personClearance(0.5);
}

TEST(PersonClearance, FarPersonReadsAsTheCap) {
  Simulation sim;
  sim.load();
  HumanBodyPoses p = personAway();
  p.hand = test::pose(1.6, 0.8, 0.3);
  p.forearm = test::pose(1.7, 0.8, 0.3);
  p.upper_arm = test::pose(1.8, 0.8, 0.3);
  p.torso = test::pose(2.0, 0.0, -0.75, 0, 0, M_PI);
  const PersonClearance c = clearanceWith(sim, p);
  EXPECT_DOUBLE_EQ(c.all, 0.5);
  EXPECT_DOUBLE_EQ(c.without_fingers, 0.5);
}

TEST(PersonClearance, NearHandWithoutContactIsPositiveAndBoundedByItsGap) {
  Simulation sim;
  sim.load();
  test::holdStep(sim, test::readyPosture());
  // the hand box (half extent 0.045 along its x) beside the palm capsule
  // (panda_hand_col_a: radius 0.028 along the hand's y, 0.03 above the flange),
  // `gap` away along the hand's x: the clearance is at most the gap (another
  // robot geom may be nearer) and positive (nothing touches)
  const Eigen::Isometry3d tcp = sim.tcpPose();
  const Eigen::Vector3d axis_point = tcp * Eigen::Vector3d(0, 0, -0.1034 + 0.03);
  const double gap = 0.02;
  HumanBodyPoses p = personAway();
  p.hand = Eigen::Isometry3d::Identity();
  p.hand.linear() = tcp.linear();
  p.hand.translation() = axis_point + tcp.linear().col(0) * (0.028 + 0.045 + gap);
  const PersonClearance c = clearanceWith(sim, p);
  EXPECT_GT(c.all, 0.0);
  EXPECT_LE(c.all, gap + 1e-4);
  EXPECT_GE(c.without_fingers, c.all);
  EXPECT_EQ(sim.contacts().robot_human, 0);
}

TEST(PersonClearance, PenetrationOfHandTorsoAndHeadIsNegative) {
  Simulation sim;
  sim.load();
  test::holdStep(sim, test::readyPosture());
  const Eigen::Isometry3d tcp = sim.tcpPose();
  // the hand box centred on the palm capsule
  HumanBodyPoses p = personAway();
  p.hand = Eigen::Isometry3d::Identity();
  p.hand.translation() = tcp * Eigen::Vector3d(0, 0, -0.1034 + 0.03);
  EXPECT_LT(clearanceWith(sim, p).all, -0.01);

  // the torso box around the tcp (the person stands where the gripper is)
  const double height = sim.options().human.height;
  p = personAway();
  p.torso = test::pose(tcp.translation().x(), tcp.translation().y(), tcp.translation().z() - 0.67 * height);
  EXPECT_LT(clearanceWith(sim, p).all, -0.01);

  // the head sphere on the tcp
  p = personAway();
  p.torso = test::pose(tcp.translation().x(), tcp.translation().y(), tcp.translation().z() - 0.93 * height);
  EXPECT_LT(clearanceWith(sim, p).all, -0.01);
}

// The other arm hangs beside the torso, on the side opposite the handing
// hand (the left for the default right hand): placed through the fingertips,
// with the torso and legs beside the gripper's narrow side, it is the only
// body there, and the judge sees the fingers inside it.
TEST(PersonClearance, FreeArmHangingBesideTheTorsoIsPartOfTheTrueBody) {
  Simulation sim;
  sim.load();
  test::holdStep(sim, test::readyPosture());
  const Eigen::Isometry3d tcp = sim.tcpPose();
  const double height = sim.options().human.height;
  const scenario::BodyDimensions body = scenario::bodyDimensionsFromHeight(height);
  const scenario::HangingArm arm = scenario::freeArmInTorso(body, scenario::HandSide::Right);
  // a point of the forearm below the hip (only the legs box is beside it there)
  const Eigen::Vector3d on_arm(arm.tip.x(), arm.tip.y(), 0.45 * height);
  ASSERT_LT(on_arm.z(), arm.elbow.z());
  ASSERT_GT(on_arm.z(), arm.tip.z());
  // upright, the torso's +y (toward the free arm) along the hand's x axis (the gripper's thin side)
  Eigen::Vector3d y = tcp.linear().col(0);
  y.z() = 0.0;
  ASSERT_GT(y.norm(), 0.5);
  y.normalize();
  if (y.x() > 0.0) y = -y;  // the trunk beyond the gripper, away from the robot's own links
  Eigen::Matrix3d R;
  R.col(1) = y;
  R.col(2) = Eigen::Vector3d::UnitZ();
  R.col(0) = R.col(1).cross(R.col(2));
  HumanBodyPoses p = personAway();
  p.torso = Eigen::Isometry3d::Identity();
  p.torso.linear() = R;
  p.torso.translation() = tcp.translation() - R * on_arm;
  EXPECT_LT(clearanceWith(sim, p).all, -0.01);
  // moved 20 cm away along the arm's side, nothing of the person is within 5 cm
  p.torso.translation() -= 0.2 * y;
  EXPECT_GT(clearanceWith(sim, p).all, 0.05);
}

}  // namespace
}  // namespace handover::sim
