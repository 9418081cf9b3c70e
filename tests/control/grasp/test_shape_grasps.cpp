// Grasp families implied by primitive shapes, and that the selector reaches
// a ball and a box offered in front of the robot.
#include <gtest/gtest.h>

#include <cmath>

#include "control/grasp/grasp_selector.hpp"
#include "control/grasp/shape_grasps.hpp"
#include "tests/control/grasp/panda_fixture.hpp"

namespace handover::control::grasp {
namespace {

void expectProperRotation(const GraspSpec& s) {
  const Matrix3 R = s.placement.linear();
  EXPECT_LT((R.transpose() * R - Matrix3::Identity()).norm(), 1e-12);
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
}

TEST(ShapeGrasps, CylinderSideFortyFiveAndTop) {
  const std::vector<GraspSpec> s = shapeGraspSpecs(PrimitiveShape::kCylinder, {0.035, 0.20});
  ASSERT_EQ(s.size(), 3u);
  for (const GraspSpec& g : s) {
    expectProperRotation(g);
    EXPECT_TRUE(g.has_free_axis);
    EXPECT_EQ(g.free_axis, Vector3::UnitZ());
    EXPECT_NEAR(g.placement.linear().col(1).z(), 0.0, 1e-12);  // fingers close across the axis
  }
  EXPECT_NEAR(s[0].placement.linear().col(2).z(), 0.0, 1e-12);             // side: horizontal approach
  EXPECT_NEAR(s[1].placement.linear().col(2).z(), -std::sqrt(0.5), 1e-12);  // 45 degrees, downward
  EXPECT_NEAR(s[2].placement.linear().col(2).z(), -1.0, 1e-12);             // top
  EXPECT_NEAR(s[2].placement.translation().z(), 0.10 - 0.02, 1e-12);       // fingertips below the top face
  // a cylinder wider than the opening has none
  EXPECT_TRUE(shapeGraspSpecs(PrimitiveShape::kCylinder, {0.05, 0.20}).empty());
}

TEST(ShapeGrasps, SphereOnlyWhenItFits) {
  EXPECT_EQ(shapeGraspSpecs(PrimitiveShape::kSphere, {0.03}).size(), 3u);
  EXPECT_TRUE(shapeGraspSpecs(PrimitiveShape::kSphere, {0.05}).empty());
  for (const GraspSpec& g : shapeGraspSpecs(PrimitiveShape::kSphere, {0.03})) {
    EXPECT_LT(g.placement.translation().norm(), 1e-15);  // through the centre
  }
}

TEST(ShapeGrasps, BoxClosesAcrossEdgesThatFit) {
  // only the 5 cm edge fits: approaches along y and z, from both sides, each at the middle of
  // the third edge and 2.5 cm (end_inset) from either of its ends
  const std::vector<GraspSpec> s = shapeGraspSpecs(PrimitiveShape::kBox, {0.05, 0.15, 0.20});
  ASSERT_EQ(s.size(), 12u);
  int middle = 0, toward_ends = 0;
  for (const GraspSpec& g : s) {
    expectProperRotation(g);
    EXPECT_FALSE(g.has_free_axis);
    EXPECT_NEAR(std::abs(g.placement.linear().col(1).x()), 1.0, 1e-12);  // fingers along the box x
    // the TCP sits `depth` inside the face it comes through ...
    const Vector3 z = g.placement.linear().col(2);
    const Vector3 p = g.placement.translation();
    const bool along_y = std::abs(z.y()) > 0.5;
    const double half = along_y ? 0.075 : 0.10;
    EXPECT_NEAR(-z.dot(p), half - 0.02, 1e-12);
    // ... on the approach line, or moved along the third edge (z for an approach along y, y for
    // one along z) to end_inset from one of its ends
    const Vector3 across_line = p - (-z.dot(p)) * -z;
    const double third_half = along_y ? 0.10 : 0.075;
    const double shift = along_y ? across_line.z() : across_line.y();
    EXPECT_NEAR(across_line.x(), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(across_line.norm() - std::abs(shift)), 0.0, 1e-12);
    if (std::abs(shift) < 1e-12) {
      ++middle;
    } else {
      EXPECT_NEAR(std::abs(shift), third_half - 0.025, 1e-12);
      ++toward_ends;
    }
  }
  EXPECT_EQ(middle, 4);
  EXPECT_EQ(toward_ends, 8);
  // a 5 cm cube: no edge long enough for grasps toward its ends (each its middle)
  EXPECT_EQ(shapeGraspSpecs(PrimitiveShape::kBox, {0.05, 0.05, 0.05}).size(), 12u);
  EXPECT_TRUE(shapeGraspSpecs(PrimitiveShape::kBox, {0.1, 0.1, 0.1}).empty());
}

TEST(ShapeGrasps, ATallBoxHeldHighByItsMiddleIsTakenByItsFreeEnd) {
  // g91_00949: a box 13 cm tall held up at 0.34 m, tilted 0.4 rad away from the robot, by a
  // hand round its middle. From the top the gripper does not reach (the pre-grasp lies past
  // the stretched elbow); from the sides at the middle the palm would be in the hand. A side
  // grasp by the upper end is reachable and clear of the hand.
  const Model& model = testing::panda();
  const std::vector<double> box = {0.0519, 0.0423, 0.1287};
  Isometry X_obj = Isometry::Identity();
  X_obj.translation() = Vector3(0.688, -0.214, 0.337);
  X_obj.linear() = (Eigen::AngleAxisd(0.048, Vector3::UnitZ()) * Eigen::AngleAxisd(0.407, Vector3::UnitY()) *
                    Eigen::AngleAxisd(0.026, Vector3::UnitX()))
                       .toRotationMatrix();
  // the hand that holds it (the scenario's holds_object: the object in the hand's frame), as the
  // planner sees it: a sphere of half the hand box's longest edge at its grip point, where only
  // the fingers may go
  Isometry object_in_hand = Isometry::Identity();
  object_in_hand.translation() = Vector3(0.012, 0.0099, 0.0365);
  object_in_hand.linear() = (Eigen::AngleAxisd(0.7667, Vector3::UnitZ()) * Eigen::AngleAxisd(0.4012, Vector3::UnitY()) *
                             Eigen::AngleAxisd(0.0308, Vector3::UnitX()))
                                .toRotationMatrix();
  ObstacleCapsule hand;
  hand.a = hand.b = (X_obj * object_in_hand.inverse()).translation();
  hand.radius = 0.05;
  hand.gripper_works_here = true;
  int reachable_ends = 0, reachable_middles = 0;
  const std::vector<GraspSpec> specs = shapeGraspSpecs(PrimitiveShape::kBox, box);
  for (const GraspSpec& spec : specs) {
    GraspSelector selector(model, {spec}, testing::shippedConfig());
    const GraspChoice& c = selector.update(X_obj, testing::readyConfiguration(), &hand, 1);
    if (!c.valid) continue;
    const Vector3 p = spec.placement.translation();
    const Vector3 z = spec.placement.linear().col(2);
    const bool at_an_end = (p - (-z.dot(p)) * -z).norm() > 1e-9;
    (at_an_end ? reachable_ends : reachable_middles) += 1;
  }
  EXPECT_GT(reachable_ends, 0) << "no grasp by an end of the box is reachable clear of the hand";
  // the middles are in the hand or out of reach: the ends are what makes the box takeable
  EXPECT_EQ(reachable_middles, 0);
}

TEST(ShapeGrasps, BallAndBoxInFrontOfTheRobotAreReachedAwayFromTheLimits) {
  const Model& model = testing::panda();
  Isometry X_obj = Isometry::Identity();
  X_obj.translation() = Vector3(0.55, 0.0, 0.30);
  X_obj.linear() = Eigen::AngleAxisd(0.6, Vector3::UnitZ()).toRotationMatrix();
  for (const auto& specs : {shapeGraspSpecs(PrimitiveShape::kSphere, {0.03}),
                            shapeGraspSpecs(PrimitiveShape::kBox, {0.05, 0.15, 0.20})}) {
    GraspSelector selector(model, specs, testing::shippedConfig());
    const GraspChoice& c = selector.update(X_obj, testing::readyConfiguration());
    ASSERT_TRUE(c.valid);
    EXPECT_GE(smallestLimitDistance(model, c.q_grasp), 0.2);
    EXPECT_GE(smallestLimitDistance(model, c.q_pre_grasp), 0.2);
  }
}

}  // namespace
}  // namespace handover::control::grasp
