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
  // only the 5 cm edge fits: approaches along y and z, from both sides
  const std::vector<GraspSpec> s = shapeGraspSpecs(PrimitiveShape::kBox, {0.05, 0.15, 0.20});
  ASSERT_EQ(s.size(), 4u);
  for (const GraspSpec& g : s) {
    expectProperRotation(g);
    EXPECT_FALSE(g.has_free_axis);
    EXPECT_NEAR(std::abs(g.placement.linear().col(1).x()), 1.0, 1e-12);  // fingers along the box x
    // the TCP sits `depth` inside the face it comes through, on the approach line
    const Vector3 z = g.placement.linear().col(2);
    const Vector3 p = g.placement.translation();
    const double half = std::abs(z.y()) > 0.5 ? 0.075 : 0.10;
    EXPECT_NEAR(-z.dot(p), half - 0.02, 1e-12);
    EXPECT_LT((p - (-z.dot(p)) * -z).norm(), 1e-12);
  }
  EXPECT_EQ(shapeGraspSpecs(PrimitiveShape::kBox, {0.05, 0.05, 0.05}).size(), 12u);
  EXPECT_TRUE(shapeGraspSpecs(PrimitiveShape::kBox, {0.1, 0.1, 0.1}).empty());
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
