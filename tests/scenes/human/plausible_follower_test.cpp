#include "scenes/human/plausible_follower.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "interfaces/minimum_jerk.hpp"

using namespace handover;
using namespace handover::human;

namespace {

constexpr double kFollowerDt = 0.001;

Eigen::Isometry3d poseAt(const Eigen::Vector3d& p, double yaw = 0.0) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  X.translation() = p;
  return X;
}

// the arm's three bodies around a hand at p (the same offsets each step)
sim::HumanBodyPoses person(const Eigen::Vector3d& p, double yaw = 0.0) {
  sim::HumanBodyPoses b;
  b.hand = poseAt(p, yaw);
  b.forearm = poseAt(p + Eigen::Vector3d(0.2, 0.0, -0.05), yaw);
  b.upper_arm = poseAt(p + Eigen::Vector3d(0.45, 0.0, 0.2), yaw);
  return b;
}

}  // namespace

// What a hand can follow passes through bit for bit (ordinary replays are
// untouched): a minimum-jerk reach of 0.3 m in 0.6 s (peak 0.94 m/s).
TEST(PlausibleFollower, AMotionAHandCanMakePassesThroughUnchanged) {
  PlausibleFollower f(HandMotionLimits{}, kFollowerDt);
  const Eigen::Vector3d p0(0.85, 0.25, 0.10), p1(0.60, 0.10, 0.22);
  f.reset(person(p0));
  for (int k = 1; k <= 800; ++k) {
    const double s = minimumJerkPhase(k * kFollowerDt / 0.6);
    const sim::HumanBodyPoses target = person(p0 + s * (p1 - p0), 0.5 * s);
    const sim::HumanBodyPoses& out = f.step(target);
    ASSERT_TRUE(out.hand.isApprox(target.hand, 0.0)) << k;
    ASSERT_TRUE(out.upper_arm.isApprox(target.upper_arm, 0.0)) << k;
  }
  EXPECT_EQ(f.slowedSteps(), 0);
}

// Issue 16: a tracked person who jumps 0.15 m into the robot. The simulated
// bodies follow within the hand's speed and acceleration, arrive, and then
// pass the target through again; the steps are counted.
TEST(PlausibleFollower, AJumpIsFollowedAtAHandsSpeedAndAcceleration) {
  const HandMotionLimits lim;
  PlausibleFollower f(lim, kFollowerDt);
  const Eigen::Vector3d p0(0.55, 0.05, 0.30), p1(0.51, 0.03, 0.44);
  f.reset(person(p0));
  const sim::HumanBodyPoses target = person(p1, 0.3);
  Eigen::Vector3d last = p0, last_v = Eigen::Vector3d::Zero();
  double arrived = -1.0;
  for (int k = 1; k <= 1000; ++k) {
    const sim::HumanBodyPoses& out = f.step(target);
    const Eigen::Vector3d p = out.hand.translation();
    const Eigen::Vector3d v = (p - last) / kFollowerDt;
    ASSERT_LE(v.norm(), lim.max_speed + 1e-9) << k;
    ASSERT_LE((v - last_v).norm() / kFollowerDt, lim.max_acceleration + 1e-6) << k;
    // the forearm moves with the hand (the same gap, the same law)
    ASSERT_NEAR((out.forearm.translation() - p - Eigen::Vector3d(0.2, 0.0, -0.05)).norm(), 0.0, 1e-9) << k;
    if (arrived < 0.0 && out.hand.isApprox(target.hand, 0.0)) arrived = k * kFollowerDt;
    last = p;
    last_v = v;
  }
  // 0.146 m: about 2 sqrt(D / a) = 0.12 s at 40 m/s^2 (the speed stays below 3 m/s)
  ASSERT_GT(arrived, 0.0);
  EXPECT_GT(arrived, 0.09);
  EXPECT_LT(arrived, 0.2);
  // counted while more than kReportedGap behind
  EXPECT_GT(f.slowedSteps(), 50);
  EXPECT_LT(f.slowedSteps(), static_cast<long>(std::lround(arrived / kFollowerDt)));
  EXPECT_NEAR(f.largestGap(), (p1 - p0).norm(), 1e-12);
  // afterwards it passes through again
  const sim::HumanBodyPoses next = person(p1 + Eigen::Vector3d(0.001, 0, 0), 0.3);
  EXPECT_TRUE(f.step(next).hand.isApprox(next.hand, 0.0));
}
