#include "scenes/human/human_facts.hpp"

#include <gtest/gtest.h>

using namespace handover;
using namespace handover::human;

namespace {
scenario::ObjectSpec cylinder() {
  scenario::ObjectSpec o;
  o.shape = scenario::Shape::Cylinder;
  o.size = {0.035, 0.20};
  return o;
}
Eigen::Isometry3d at(const Eigen::Vector3d& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = p;
  return T;
}
}  // namespace

TEST(HumanFacts, DistanceToEachShape) {
  const Eigen::Isometry3d obj = at({0.5, 0, 0.3});
  EXPECT_NEAR(distanceToObject(cylinder(), obj, {0.5, 0.1, 0.3}), 0.1 - 0.035, 1e-12);   // side
  EXPECT_NEAR(distanceToObject(cylinder(), obj, {0.5, 0.0, 0.45}), 0.15 - 0.10, 1e-12);  // above the cap
  EXPECT_NEAR(distanceToObject(cylinder(), obj, {0.5, 0.0, 0.3}), 0.0, 1e-12);           // inside
  scenario::ObjectSpec box;
  box.shape = scenario::Shape::Box;
  box.size = {0.1, 0.2, 0.3};
  EXPECT_NEAR(distanceToObject(box, obj, {0.5 + 0.08, 0, 0.3}), 0.03, 1e-12);
  EXPECT_NEAR(distanceToObject(box, obj, {0.5 + 0.08, 0.14, 0.3}), std::hypot(0.03, 0.04), 1e-12);
  scenario::ObjectSpec ball;
  ball.shape = scenario::Shape::Sphere;
  ball.size = {0.04};
  EXPECT_NEAR(distanceToObject(ball, obj, {0.5, 0, 0.4}), 0.06, 1e-12);
  // the object's rotation counts: a cylinder lying along x
  Eigen::Isometry3d lying = obj;
  lying.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_NEAR(distanceToObject(cylinder(), lying, {0.5 + 0.12, 0, 0.3}), 0.02, 1e-12);
}

TEST(HumanFacts, FingersAndReach) {
  sim::ContactReport c;
  sim::ObjectState o;
  o.pose = at({0.5, 0, 0.3});
  c.left_finger_on_object = true;
  HumanFacts f = computeHumanFacts(c, o, cylinder(), at({0.5, 0.06, 0.3}));
  EXPECT_FALSE(f.fingers_on_object);  // one finger is not both
  EXPECT_FALSE(f.object_free);
  EXPECT_TRUE(f.object_in_reach);  // 2.5 cm from the surface, at rest
  c.right_finger_on_object = true;
  EXPECT_TRUE(computeHumanFacts(c, o, cylinder(), at({0.5, 0.06, 0.3})).fingers_on_object);
  c = {};
  f = computeHumanFacts(c, o, cylinder(), at({0.5, 0.07, 0.3}));  // 3.5 cm
  EXPECT_TRUE(f.object_free);
  EXPECT_FALSE(f.object_in_reach);
  o.velocity[0] = 0.06;  // close but moving faster than 5 cm/s
  EXPECT_FALSE(computeHumanFacts(c, o, cylinder(), at({0.5, 0.05, 0.3})).object_in_reach);
  o.velocity[0] = 0.04;
  EXPECT_TRUE(computeHumanFacts(c, o, cylinder(), at({0.5, 0.05, 0.3})).object_in_reach);
}
