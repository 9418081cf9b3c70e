// The cycle's grasp planner (runtime/grasp_planning.hpp): it selects on new
// samples only, for the object while the person holds it and for the hand
// while the robot does; its choice is a candidate the arm reaches (IK checked
// here with forward kinematics); the declared grasp is preferred; a held
// object is placed upright.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "control/grasp/shape_grasps.hpp"
#include "runtime/grasp_planning.hpp"
#include "tests/control/grasp/panda_fixture.hpp"

namespace handover::runtime {
namespace {

namespace cg = control::grasp;
using cg::testing::panda;
using cg::testing::readyConfiguration;
using cg::testing::shippedConfig;
using cg::testing::tcpPose;

/// An upright bottle (radius 3 cm, 20 cm) declared with a side grasp, free about z.
GraspPlanningSettings bottleSettings(bool with_shape_families) {
  GraspPlanningSettings s;
  s.config = shippedConfig();
  cg::GraspSpec side;
  side.placement.linear() = Eigen::AngleAxisd(M_PI / 2, control::Vector3::UnitY()).toRotationMatrix();
  side.has_free_axis = true;
  side.preference = s.config.declared_preference;
  s.object_grasps.push_back(side);
  if (with_shape_families)
    for (const auto& g : cg::shapeGraspSpecs(cg::PrimitiveShape::kCylinder, {0.03, 0.20})) s.object_grasps.push_back(g);
  s.presentation.translation() = control::Vector3(0.0, 0.0, 0.05);
  s.presentation.linear() = side.placement.linear();
  return s;
}

/// Settings for a give whose object is held from the top: the TCP pointing
/// down, `height` (m) above the receiver's grip point.
GraspPlanningSettings topPresentation(double height) {
  GraspPlanningSettings s = bottleSettings(false);
  s.presentation = control::Isometry::Identity();
  s.presentation.linear() = Eigen::AngleAxisd(M_PI, control::Vector3::UnitX()).toRotationMatrix();
  s.presentation.translation() = control::Vector3(0.0, 0.0, height);
  return s;
}

/// The person holds the bottle out in front of the robot.
perception::PerceptionEstimate offered(double stamp, const control::Vector3& at) {
  perception::PerceptionEstimate e;
  e.time = stamp;
  e.human.valid = true;
  e.human.stale = false;
  e.human.stamp = stamp;
  e.human.hand.translation() = at - control::Vector3(0.0, 0.0, 0.08);
  e.human.forearm.translation() = at + control::Vector3(0.30, 0.0, -0.10);  // elbow behind, toward the person
  e.human.forearm.linear() = Eigen::AngleAxisd(-M_PI / 2, control::Vector3::UnitY()).toRotationMatrix();
  e.human.upper_arm.translation() = at + control::Vector3(0.35, 0.0, 0.25);
  e.object.valid = true;
  e.object.stale = false;
  e.object.holder = perception::ObjectHolder::Person;
  e.object.pose.translation() = at;
  return e;
}

TEST(GraspPlanning, ChoosesAReachableDeclaredGraspOnNewSamples) {
  GraspPlanning planning(panda(), bottleSettings(false));
  const control::Vector3 at(0.55, 0.1, 0.35);
  planning.update(offered(0.1, at), readyConfiguration(), false);
  const fsm::TrackingPlan& plan = planning.objectPlan();
  ASSERT_TRUE(plan.valid);
  EXPECT_FALSE(planning.handPlan().valid);
  // the IK configuration puts the TCP on the chosen grasp frame
  const control::Isometry grasp = offered(0.1, at).object.pose * plan.target_in_observed;
  const control::Isometry tcp = tcpPose(panda(), plan.q_target);
  EXPECT_LT((tcp.translation() - grasp.translation()).norm(), 1e-3);
  EXPECT_LT(Eigen::AngleAxisd(tcp.linear().transpose() * grasp.linear()).angle(), 0.01);
  // a side grasp (approach axis horizontal) from the declared spec: reachable here
  const control::Vector3 approach = grasp.linear().col(2);
  EXPECT_LT(std::abs(approach.z()), 1e-6);
  const int spec = planning.objectSelector().candidates()[static_cast<std::size_t>(plan.index)].spec;
  EXPECT_EQ(spec, 0);
  // the same sample again changes nothing (selection runs on new samples)
  const fsm::TrackingPlan before = plan;
  planning.update(offered(0.1, at + control::Vector3(0.0, 0.2, 0.0)), readyConfiguration(), false);
  EXPECT_TRUE(planning.objectPlan().target_in_observed.isApprox(before.target_in_observed));
  EXPECT_TRUE(planning.objectPlan().q_target.isApprox(before.q_target));
}

TEST(GraspPlanning, ShapeFamiliesServeWhereTheDeclaredGraspIsOutOfReach) {
  // a declared grasp from underneath, the object held low: no arm configuration
  // reaches under it without going through the table
  GraspPlanningSettings s = bottleSettings(true);
  s.object_grasps[0].placement.linear() = control::Matrix3::Identity();  // approach along +z: from below
  s.object_grasps[0].has_free_axis = false;
  GraspPlanning planning(panda(), s);
  planning.update(offered(0.1, control::Vector3(0.5, 0.0, 0.12)), readyConfiguration(), false);
  ASSERT_TRUE(planning.objectPlan().valid);
  const int spec =
      planning.objectSelector().candidates()[static_cast<std::size_t>(planning.objectPlan().index)].spec;
  EXPECT_GT(spec, 0);  // one of the shape's families
  GraspPlanningSettings declared_only = s;
  declared_only.object_grasps.resize(1);
  GraspPlanning strict(panda(), declared_only);
  strict.update(offered(0.1, control::Vector3(0.5, 0.0, 0.12)), readyConfiguration(), false);
  EXPECT_FALSE(strict.objectPlan().valid);
}

TEST(GraspPlanning, WhileTheRobotHoldsItPlansThePresentationToTheHand) {
  GraspPlanning planning(panda(), bottleSettings(false));
  perception::PerceptionEstimate e = offered(0.2, control::Vector3(0.55, -0.1, 0.35));
  e.object.holder = perception::ObjectHolder::Robot;
  planning.update(e, readyConfiguration(), true);
  EXPECT_FALSE(planning.objectPlan().valid);
  ASSERT_TRUE(planning.handPlan().valid);
  const control::Isometry tcp_in_hand = planning.handPlan().target_in_observed;
  // turned about the hand's vertical only: the held object stays upright
  EXPECT_NEAR(tcp_in_hand.translation().z(), 0.05, 1e-9);
  EXPECT_NEAR(tcp_in_hand.linear().col(2).z(), 0.0, 1e-9);
  const control::Isometry tcp = tcpPose(panda(), planning.handPlan().q_target);
  EXPECT_LT((tcp.translation() - (e.human.hand * tcp_in_hand).translation()).norm(), 1e-3);
}

TEST(GraspPlanning, UprightPlacementKeepsTheHeldObjectVertical) {
  GraspPlanning planning(panda(), bottleSettings(false));
  const control::Isometry object_in_tcp = bottleSettings(false).object_grasps[0].placement.inverse();
  const fsm::ArmPlacement p = planning.uprightPlacement(object_in_tcp, control::Vector3::UnitZ(),
                                                        control::Vector3(0.35, 0.0, 0.45), readyConfiguration());
  ASSERT_TRUE(p.found);
  const control::Isometry object = tcpPose(panda(), p.q) * object_in_tcp;
  EXPECT_GT(object.linear().col(2).z(), std::cos(10.0 * M_PI / 180.0));
  EXPECT_LT((p.tcp.translation() - tcpPose(panda(), p.q).translation()).norm(), 1e-3);
}

}  // namespace
}  // namespace handover::runtime

namespace handover::runtime {
namespace {
TEST(GraspPlanning, APresentationIsPlannedWithoutAPreGraspBackedOffFromIt) {
  // the object is brought straight to the hand (ApproachHand has no standoff):
  // a high hand, where the gripper pointing down reaches the presentation but
  // not a pose 8 cm above it, still gets a plan
  GraspPlanningSettings s = topPresentation(0.08);
  GraspPlanning planning(panda(), s);
  const control::Vector3 hand(0.65, 0.06, 0.45);
  perception::PerceptionEstimate e = offered(0.2, hand + control::Vector3(0.0, 0.0, 0.08));
  e.object.holder = perception::ObjectHolder::Robot;
  planning.update(e, readyConfiguration(), true);
  ASSERT_TRUE(planning.handPlan().valid);
  const control::Isometry tcp = tcpPose(panda(), planning.handPlan().q_target);
  EXPECT_LT((tcp.translation() - (e.human.hand * planning.handPlan().target_in_observed).translation()).norm(), 1e-3);
}
}  // namespace
}  // namespace handover::runtime

namespace handover::runtime {
namespace {
TEST(GraspPlanning, AHandBeyondAnUprightPresentationGetsATiltedOne) {
  // a ball held from the top, a receiver's hand high and far: with the
  // gripper pointing down the wrist is out of the arm's reach; tilted by up to
  // presentation_tilt, the same ball reaches the same place in the hand
  GraspPlanningSettings s = topPresentation(0.05);
  s.presentation_pivot = control::Vector3(0.0, 0.0, 0.05);
  const control::Vector3 hand(0.68, 0.0, 0.56);
  perception::PerceptionEstimate e = offered(0.2, hand + control::Vector3(0.0, 0.0, 0.08));
  e.object.holder = perception::ObjectHolder::Robot;

  s.config.presentation_tilt = 0.0;
  GraspPlanning upright_only(panda(), s);
  upright_only.update(e, readyConfiguration(), true);
  EXPECT_FALSE(upright_only.handPlan().valid);

  s.config.presentation_tilt = 30.0 * M_PI / 180.0;
  GraspPlanning tilting(panda(), s);
  tilting.update(e, readyConfiguration(), true);
  ASSERT_TRUE(tilting.handPlan().valid);
  const control::Isometry tcp_in_hand = tilting.handPlan().target_in_observed;
  EXPECT_LT((tcp_in_hand.translation() - s.presentation_pivot).norm(), 1e-9);  // the ball where it was
  const double tilt = std::acos(std::clamp(-tcp_in_hand.linear().col(2).z(), -1.0, 1.0));
  EXPECT_NEAR(tilt, s.config.presentation_tilt, 1e-9);
  const control::Isometry tcp = tcpPose(panda(), tilting.handPlan().q_target);
  EXPECT_LT((tcp.translation() - (e.human.hand * tcp_in_hand).translation()).norm(), 1e-3);
}
}  // namespace
}  // namespace handover::runtime
