// The one tracking-offset rule: on the object it keeps the object's symmetry,
// approaches from the robot's base and lets an empty parallel gripper use
// either finger; on the hand it does none of these. The placement passes
// through unchanged either way.
#include <gtest/gtest.h>

#include "runtime/adapter/tracking_offset_rule.hpp"

namespace handover::runtime {
namespace {

control::GraspOffset symmetricBottle() {
  control::GraspOffset g;
  g.placement.translation() = control::Vector3(0.0, 0.0, 0.05);
  g.has_free_axis = true;
  g.free_axis = control::Vector3::UnitX();
  return g;
}

TEST(TrackingOffsetRule, OnTheObjectKeepsItsSymmetryAndBothFingerings) {
  control::Isometry pre = control::Isometry::Identity();
  pre.translation() = control::Vector3(0.0, 0.0, -0.08);
  const control::GraspOffset g = makeTrackingOffset(pre, symmetricBottle(), true);
  EXPECT_TRUE(g.placement.matrix() == pre.matrix());
  EXPECT_TRUE(g.has_free_axis);
  EXPECT_TRUE(g.free_axis == control::Vector3::UnitX());
  EXPECT_TRUE(g.approach_from_base);
  EXPECT_TRUE(g.base.isZero());
  EXPECT_TRUE(g.parallel_gripper);
}

TEST(TrackingOffsetRule, OnTheHandIsARigidOffset) {
  const control::Isometry placement = symmetricBottle().placement;
  const control::GraspOffset g = makeTrackingOffset(placement, symmetricBottle(), false);
  EXPECT_TRUE(g.placement.matrix() == placement.matrix());
  EXPECT_FALSE(g.has_free_axis);
  EXPECT_FALSE(g.parallel_gripper);
}

TEST(TrackingOffsetRule, AnObjectWithoutSymmetryGetsNone) {
  control::GraspOffset box;  // no free axis
  const control::GraspOffset g = makeTrackingOffset(control::Isometry::Identity(), box, true);
  EXPECT_FALSE(g.has_free_axis);
  EXPECT_TRUE(g.parallel_gripper);
}

TEST(TrackingOffsetRule, APlannedOffsetIsTrackedExactlyWithItsJointPlan) {
  control::Vector7 q_plan;
  q_plan << 0.1, -0.4, 0.2, -2.0, 0.3, 1.9, -1.7;
  const control::GraspOffset g = makeTrackingOffset(symmetricBottle().placement, symmetricBottle(), true, true, q_plan);
  EXPECT_FALSE(g.has_free_axis);
  EXPECT_FALSE(g.approach_from_base);
  EXPECT_FALSE(g.parallel_gripper);
  EXPECT_TRUE(g.has_joint_plan);
  EXPECT_TRUE(g.joint_plan == q_plan);
  // an unplanned offset carries none: the turn is the shortest
  EXPECT_FALSE(makeTrackingOffset(symmetricBottle().placement, symmetricBottle(), true).has_joint_plan);
}

}  // namespace
}  // namespace handover::runtime
