// liftOffDirection (fsm/handover/lift_off.hpp): back the way the gripper came
// in, never lower, at least the given elevation.
#include <gtest/gtest.h>

#include <cmath>

#include "fsm/handover/lift_off.hpp"

namespace handover::fsm {
namespace {

constexpr double kElevation = M_PI / 4.0;

/// A TCP at `at` whose approach axis (z) points along `approach`.
Isometry tcpApproaching(const Vector3& approach, const Vector3& at) {
  Isometry T = Isometry::Identity();
  T.linear() = Eigen::Quaterniond::FromTwoVectors(Vector3::UnitZ(), approach.normalized()).toRotationMatrix();
  T.translation() = at;
  return T;
}

double elevation(const Vector3& d) { return std::atan2(d.z(), d.head<2>().norm()); }

TEST(LiftOff, AGraspFromAboveLiftsStraightUp) {
  const Vector3 d = liftOffDirection(tcpApproaching(-Vector3::UnitZ(), Vector3(0.6, 0.1, 0.5)), kElevation);
  EXPECT_NEAR((d - Vector3::UnitZ()).norm(), 0.0, 1e-9);
}

TEST(LiftOff, AGraspFromTheSideDrawsBackAndUp) {
  // the gripper came in along +x (away from the base): back is -x, raised to 45 degrees
  const Vector3 d = liftOffDirection(tcpApproaching(Vector3::UnitX(), Vector3(0.6, 0.0, 0.5)), kElevation);
  EXPECT_NEAR(d.norm(), 1.0, 1e-12);
  EXPECT_LT(d.x(), 0.0);
  EXPECT_NEAR(d.y(), 0.0, 1e-9);
  EXPECT_NEAR(elevation(d), kElevation, 1e-9);
}

TEST(LiftOff, ASteepApproachKeepsItsOwnElevation) {
  // came in 60 degrees downward: back is 60 degrees upward, more than the minimum
  const Vector3 approach(std::cos(M_PI / 3.0), 0.0, -std::sin(M_PI / 3.0));
  const Vector3 d = liftOffDirection(tcpApproaching(approach, Vector3(0.6, 0.0, 0.5)), kElevation);
  EXPECT_NEAR((d + approach).norm(), 0.0, 1e-9);
}

TEST(LiftOff, AGraspFromBelowNeverGoesDown) {
  // came in upward at 30 degrees: back would be downward; only its horizontal part is kept
  const Vector3 approach(std::cos(M_PI / 6.0), 0.0, std::sin(M_PI / 6.0));
  const Vector3 d = liftOffDirection(tcpApproaching(approach, Vector3(0.6, 0.0, 0.5)), kElevation);
  EXPECT_LT(d.x(), 0.0);
  EXPECT_NEAR(elevation(d), kElevation, 1e-9);
  // straight up from below: nothing left of the axis, back toward the base
  const Vector3 home = liftOffDirection(tcpApproaching(Vector3::UnitZ(), Vector3(0.0, 0.6, 0.5)), kElevation);
  EXPECT_LT(home.y(), 0.0);
  EXPECT_NEAR(home.x(), 0.0, 1e-9);
  EXPECT_NEAR(elevation(home), kElevation, 1e-9);
}

}  // namespace
}  // namespace handover::fsm
