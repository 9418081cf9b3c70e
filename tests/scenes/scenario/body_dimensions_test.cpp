#include "scenes/scenario/body_dimensions.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace handover::scenario;

TEST(BodyDimensions, MatchFactsFileSegmentsAt50thPercentile) {
  // facts file: 1.759 m male has upper arm 0.361, forearm + hand 0.483
  const BodyDimensions m = bodyDimensionsFromHeight(1.759);
  EXPECT_NEAR(m.upper_arm, 0.361, 0.005);
  EXPECT_NEAR(m.forearm + 0.108 * 1.759, 0.483, 0.015);
  const BodyDimensions f = bodyDimensionsFromHeight(1.618);
  EXPECT_NEAR(f.upper_arm, 0.332, 0.005);
  EXPECT_NEAR(f.forearm + 0.108 * 1.618, 0.428, 0.015);
  // a person reaches less than their height's half and more than a third
  EXPECT_GT(m.reach(), 0.33 * 1.759);
  EXPECT_LT(m.reach(), 0.5 * 1.759);
}

TEST(BodyDimensions, ShoulderSidesFollowFacing) {
  const BodyDimensions b = bodyDimensionsFromHeight(1.75);
  // facing the robot (yaw = pi): the right shoulder is at +y
  const Eigen::Vector3d r = shoulderPosition(b, {1.0, 0.0}, M_PI, HandSide::Right);
  const Eigen::Vector3d l = shoulderPosition(b, {1.0, 0.0}, M_PI, HandSide::Left);
  EXPECT_GT(r.y(), 0.1);
  EXPECT_LT(l.y(), -0.1);
  EXPECT_NEAR(r.x(), 1.0, 1e-9);
  EXPECT_NEAR(r.z(), kFloorZ + b.shoulder_height, 1e-12);
  // facing +x (yaw = 0): the right shoulder is at -y
  EXPECT_LT(shoulderPosition(b, {0, 0}, 0.0, HandSide::Right).y(), -0.1);
}

TEST(BodyDimensions, FreeArmHangsBesideTheTorsoOppositeTheHandingArm) {
  const BodyDimensions b = bodyDimensionsFromHeight(1.759);
  const HangingArm right_hands = freeArmInTorso(b, HandSide::Right);
  const HangingArm left_hands = freeArmInTorso(b, HandSide::Left);
  // torso frame +y is the person's left: a right-handed giver's free arm is there,
  // its capsule clear of the torso box
  EXPECT_GE(right_hands.shoulder.y() - b.upper_arm_radius, 0.5 * b.torso_width - 1e-12);
  EXPECT_LE(left_hands.shoulder.y() + b.upper_arm_radius, -0.5 * b.torso_width + 1e-12);
  EXPECT_NEAR(right_hands.shoulder.z(), b.shoulder_height, 1e-12);
  // facts file: upper arm 0.361, forearm + hand 0.483 for a 1.759 m person
  EXPECT_NEAR((right_hands.elbow - right_hands.shoulder).norm(), 0.361, 0.005);
  const double fingertip = right_hands.tip.z() - b.forearm_radius;
  EXPECT_NEAR(right_hands.elbow.z() - fingertip, 0.483, 0.015);
  // hanging: straight down, fingertips above the floor, below the hip
  EXPECT_NEAR(right_hands.tip.x(), 0.0, 1e-12);
  EXPECT_NEAR(right_hands.tip.y(), right_hands.shoulder.y(), 1e-12);
  EXPECT_GT(fingertip, 0.0);
  EXPECT_LT(fingertip, b.hip_height);
}
