// The benchmark factors of a scenario, derived from its geometry.
#include "scenes/scenario/scenario_category.hpp"

#include <gtest/gtest.h>

#include <string>

#include "config/input_error.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace handover::scenario {
namespace {

constexpr double kPi = 3.14159265358979323846;

ObjectSpec objectWithApproach(const Eigen::Vector3d& rpy, int free_axis = -1) {
  ObjectSpec o;
  o.grasp.linear() = rotationFromRpy(rpy);
  o.free_axis = free_axis;
  return o;
}

TEST(GraspFamily, ByTheAngleBetweenApproachAndDown) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(graspFamily(objectWithApproach({kPi, 0, 0}), up), "top");        // approach -z
  EXPECT_EQ(graspFamily(objectWithApproach({0, 0.5 * kPi, 0}), up), "side");  // approach +x
  EXPECT_EQ(graspFamily(objectWithApproach({0, 0.75 * kPi, 0}), up), "angled");
  EXPECT_EQ(graspFamily(objectWithApproach({0, 0, 0}), up), "below");         // approach +z: from underneath
  // 20 deg off the vertical is still from the top, 25 deg is angled
  EXPECT_EQ(graspFamily(objectWithApproach({0, kPi - 20.0 * kPi / 180, 0}), up), "top");
  EXPECT_EQ(graspFamily(objectWithApproach({0, kPi - 25.0 * kPi / 180, 0}), up), "angled");
}

TEST(GraspFamily, AroundAFreeAxisThatLies) {
  // a side grasp of a cylinder free about z: upright it is a side grasp; lying
  // (its x axis up) the approach goes round the axis
  const ObjectSpec o = objectWithApproach({0, 0.5 * kPi, 0}, 2);
  EXPECT_EQ(graspFamily(o, Eigen::Vector3d::UnitZ()), "side");
  EXPECT_EQ(graspFamily(o, Eigen::Vector3d::UnitX()), "around_axis");
  // not around the axis when the approach runs along it
  EXPECT_EQ(graspFamily(objectWithApproach({kPi, 0, 0}, 2), Eigen::Vector3d::UnitX()), "side");
}

TEST(StandPlacement, FrontOffsetSide) {
  EXPECT_EQ(standPlacement({1.0, 0.0}), "front");
  EXPECT_EQ(standPlacement({1.0, -0.3}), "offset");
  EXPECT_EQ(standPlacement({0.5, 0.8}), "side");
}

TEST(CategoryOf, ShippedScenarios) {
  const std::string dir = std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios/";
  const Category d = categoryOf(parseScenario(dir + "default.yaml"));
  EXPECT_EQ(d.direction, "take");
  EXPECT_EQ(d.grasp, "top");
  EXPECT_EQ(d.shape, "cylinder");
  EXPECT_EQ(d.behaviour, "file");
  EXPECT_EQ(d.placement, "front");
  EXPECT_EQ(d.hand, "right");
  EXPECT_EQ(d.height, "mid");  // reach target z = 0.30
  EXPECT_EQ(categoryLabel(d), "take/top/cylinder/file");
  const Category g = categoryOf(parseScenario(dir + "r2h_withdraw_retry.yaml"));
  EXPECT_EQ(g.direction, "give");
  EXPECT_EQ(g.shape, "sphere");
  const Category f = categoryOf(parseScenario(dir + "h2r_forearm_in_way.yaml"));
  EXPECT_EQ(f.placement, "side");
  EXPECT_EQ(f.hand, "left");
}

// a take of a bottle held with `holds_rpy` in the hand, plus `extra` lines
std::string bottleTake(const std::string& holds_rpy, const std::string& extra) {
  return R"(
name: b
mode: human_to_robot
duration: 10
object: {shape: cylinder, size: [0.03, 0.2], mass: 0.3, grasp: {pos: [0, 0, 0.06], rpy: [3.1416, 0, 0]}}
human:
  stand: {pos: [1.0, 0.0], yaw: 3.1416}
  height: 1.75
  start: {pos: [0.85, 0.25, 0.10]}
  holds_object: {pos: [0, 0, 0.04], rpy: )" +
         holds_rpy + R"(}
  script:
    - reach: {pos: [0.55, 0.05, 0.30], duration: 1.0}
)" + extra;
}

TEST(CategoryOf, PresentationTiltDoesNotChangeTheFamily) {
  // a bottle held tilted by 20 deg is still taken from the top
  const Category c = categoryOf(parseScenarioString(bottleTake("[0.35, 0, 0]", "behaviour: plain\n"), "tilted.yaml"));
  EXPECT_EQ(c.grasp, "top");
  EXPECT_EQ(c.behaviour, "plain");
}

TEST(Behaviour, MustBeOneLowercaseWord) {
  const std::string base = bottleTake("[0, 0, 0]", "");
  EXPECT_NO_THROW(parseScenarioString(base + "behaviour: late_release\n", "b.yaml"));
  EXPECT_THROW(parseScenarioString(base + "behaviour: Late Release\n", "b.yaml"), InputError);
}

}  // namespace
}  // namespace handover::scenario
