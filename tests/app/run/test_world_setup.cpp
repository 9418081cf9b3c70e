// The world as a run sets it up from a scenario (app/run/world_setup.hpp):
// the object a give starts with sits against the palm, never inside it.
#include <gtest/gtest.h>

#include <cmath>

#include "app/run/world_setup.hpp"
#include "scenes/scenario/object_geometry.hpp"

namespace handover::app {
namespace {

// the benchmark's g317_00260: a box 10 x 6.3 x 21 cm held at 45 degrees
// 4.5 cm below its top face; the top edge lies under the palm
scenario::Scenario angledBoxGive() {
  scenario::Scenario sc;
  sc.mode = scenario::Mode::RobotToHuman;
  sc.robot.holds_object = true;
  sc.object.shape = scenario::Shape::Box;
  sc.object.size = {0.099, 0.0633, 0.2124};
  sc.object.grasp.linear() = (Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX())).toRotationMatrix();
  sc.object.grasp.translation() = Eigen::Vector3d(0, 0, 0.0612);
  return sc;
}

TEST(RobotHeldObject, AGivesGraspDeeperThanThePalmIsHeldInFrontOfIt) {
  const control::grasp::PalmGeometry palm;
  const scenario::Scenario sc = angledBoxGive();
  const io::ObjectShape solid = scenario::primitiveShapeOf(sc.object);
  ASSERT_GT(control::grasp::palmShift(solid, sc.object.grasp, palm), 0.01);  // the premise
  const scenario::ObjectSpec held = robotHeldObject(sc, palm);
  EXPECT_LT(control::grasp::palmShift(solid, held.grasp, palm), 0.004);
  // moved back along its approach axis, turned nowhere
  const Eigen::Vector3d moved = sc.object.grasp.translation() - held.grasp.translation();
  EXPECT_GT(moved.dot(sc.object.grasp.linear().col(2)), 0.01);
  EXPECT_NEAR(moved.cross(sc.object.grasp.linear().col(2)).norm(), 0.0, 1e-12);
  EXPECT_LT((held.grasp.linear() - sc.object.grasp.linear()).norm(), 1e-12);
}

TEST(RobotHeldObject, ATakesObjectIsLeftAsDeclared) {
  scenario::Scenario sc = angledBoxGive();
  sc.mode = scenario::Mode::HumanToRobot;
  sc.robot.holds_object = false;
  const scenario::ObjectSpec held = robotHeldObject(sc, control::grasp::PalmGeometry{});
  EXPECT_TRUE(held.grasp.isApprox(sc.object.grasp, 1e-15));
}

}  // namespace
}  // namespace handover::app
