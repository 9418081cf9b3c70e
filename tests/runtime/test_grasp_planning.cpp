// The cycle's grasp planner (runtime/grasp_planning.hpp): it selects on new
// samples only, for the object while the person holds it and for the hand
// while the robot does; its choice is a candidate the arm reaches (IK checked
// here with forward kinematics); the declared grasp is preferred; a held
// object is placed upright.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "control/grasp/clearance.hpp"
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
                                                        control::Vector3(0.35, 0.0, 0.45), readyConfiguration(), 0.0);
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
// A receiver takes the object back toward their body: the pull the
// presentation keeps free points from the hand to the shoulder, level.
TEST(GraspPlanning, AReceiverPullsTowardTheirShoulderLevel) {
  perception::HumanEstimate person;
  person.hand.translation() = control::Vector3(0.55, -0.20, 0.30);
  person.upper_arm.translation() = control::Vector3(0.95, 0.10, 0.75);
  const control::Vector3 pull = receiverPull(person);
  EXPECT_NEAR(pull.norm(), 1.0, 1e-12);
  EXPECT_NEAR(pull.z(), 0.0, 1e-12);
  EXPECT_NEAR(pull.x(), 0.8, 1e-12);
  EXPECT_NEAR(pull.y(), 0.6, 1e-12);
  // a shoulder straight above the hand says nothing about the way out
  person.upper_arm.translation() = person.hand.translation() + control::Vector3(0.0, 0.0, 0.4);
  EXPECT_EQ(receiverPull(person), control::Vector3::Zero());
}

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

namespace handover::runtime {
namespace {
// how far the collision constraints hold the gripper at TCP pose `tcp_in_hand`
// (hand frame) short of itself at the receiver's hand box
double presentationShortfall(const GraspPlanningSettings& s, const perception::PerceptionEstimate& e,
                             const control::Vector7& q) {
  cg::ObstacleCapsule box;
  box.a = box.b = (e.human.hand * s.hand_box).translation();
  box.box_axes = (e.human.hand * s.hand_box).linear();
  box.box_half_extents = s.hand_box_half_extents;
  box.keep_only = true;
  box.keep_arm = s.keeps.hand.arm;
  box.keep_gripper = s.keeps.hand.gripper;
  cg::ChainPoses poses;
  cg::chainPoses(panda(), q, poses);
  return cg::keepShortfall(panda(), poses, &box, 1);
}

// The same ball on the same high palm: tilted across the fingers' closing
// axis, one fingertip dips toward the palm and the constraint that keeps the
// gripper off the hand held the ball 3 cm high, out of the receiver's reach
// (g137_00521); knowing the hand box and that keep, the planner tilts the
// ball along the closing axis, the fingers level over the palm.
TEST(GraspPlanning, ATiltedPresentationKeepsTheFingersOffTheReceiversPalm) {
  GraspPlanningSettings s = topPresentation(0.05);
  s.config.score.exit = 0.0;  // the shortfall alone (the receiver's pull would also turn the blind choice)
  s.presentation_pivot = control::Vector3(0.0, 0.0, 0.05);
  s.keeps.hand.gripper = 0.021;  // the shipped apart rule: sDist and the sensing budget
  s.keeps.hand.arm = 0.04;
  const control::Vector3 hand(0.68, 0.0, 0.56);
  perception::PerceptionEstimate e = offered(0.2, hand + control::Vector3(0.0, 0.0, 0.08));
  e.object.holder = perception::ObjectHolder::Robot;
  s.hand_box_half_extents = control::Vector3(0.045, 0.04, 0.015);

  GraspPlanning knowing(panda(), s);
  knowing.update(e, readyConfiguration(), true);
  ASSERT_TRUE(knowing.handPlan().valid);
  const double kept = presentationShortfall(s, e, knowing.handPlan().q_target);

  GraspPlanningSettings blind_settings = s;
  blind_settings.hand_box_half_extents.setZero();  // the hand unknown to the planner
  GraspPlanning blind(panda(), blind_settings);
  blind.update(e, readyConfiguration(), true);
  ASSERT_TRUE(blind.handPlan().valid);
  const double held = presentationShortfall(s, e, blind.handPlan().q_target);
  EXPECT_LT(kept, 0.005) << "the fingers dip toward the palm";
  EXPECT_GT(held, 0.02) << "without the hand box the planner tilts across the fingers too";
}
}  // namespace
}  // namespace handover::runtime

namespace handover::runtime {
namespace {
// the trunk as selector capsules: inside the collision model's torso box,
// reaching its top, bottom, front and sides; the head and the free arm as declared
TEST(GraspPlanning, TheTrunkCapsulesFillTheTorsoBoxWithoutLeavingIt) {
  control::PersonTrunk trunk;  // a 1.75 m person
  const std::vector<cg::ObstacleCapsule> caps = trunkObstacles(trunk, 0.045);
  ASSERT_EQ(caps.size(), 4u);
  ASSERT_LE(static_cast<int>(caps.size()), kMaxTrunkObstacles);
  const control::Vector3 half = 0.5 * trunk.torso_size;
  const control::Vector3 centre(0.0, 0.0, trunk.torso_centre);
  control::Vector3 lo = control::Vector3::Constant(1e9), hi = -lo;
  for (int k = 0; k < 2; ++k) {
    const cg::ObstacleCapsule& c = caps[static_cast<std::size_t>(k)];
    for (const control::Vector3& p : {c.a, c.b})
      for (int axis = 0; axis < 3; ++axis)
        for (double s : {-1.0, 1.0}) {
          const control::Vector3 surface = p + s * c.radius * control::Vector3::Unit(axis) - centre;
          EXPECT_LE(std::abs(surface(axis)), half(axis) + 1e-12);
          lo(axis) = std::min(lo(axis), surface(axis));
          hi(axis) = std::max(hi(axis), surface(axis));
        }
  }
  EXPECT_TRUE(lo.isApprox(-half, 1e-12)) << lo.transpose();
  EXPECT_TRUE(hi.isApprox(half, 1e-12)) << hi.transpose();
  EXPECT_EQ(caps[2].a, control::Vector3(0.0, 0.0, trunk.head_centre));
  EXPECT_EQ(caps[2].radius, trunk.head_radius);
  EXPECT_EQ(caps[3].a, trunk.free_arm_top);
  EXPECT_EQ(caps[3].b, trunk.free_arm_bottom);
  for (const cg::ObstacleCapsule& c : caps) EXPECT_FALSE(c.gripper_works_here);
}

// a person whose chest stands where the unobstructed choice puts the arm: with
// the trunk known, no configuration the planner accepts comes nearer the
// trunk than the collision constraints keep the arm from it
TEST(GraspPlanning, NoPlannedConfigurationPressesTheArmIntoThePersonsTrunk) {
  GraspPlanningSettings s = bottleSettings(true);
  s.trunk = trunkObstacles(control::PersonTrunk{}, 0.045);
  s.keeps.trunk = {0.04, 0.04};  // what config/collision.yaml's person_trunk rule keeps
  const control::Vector3 at(0.55, 0.1, 0.35);
  GraspPlanning free_planning(panda(), s);
  free_planning.update(offered(0.1, at), readyConfiguration(), false);
  ASSERT_TRUE(free_planning.objectPlan().valid);
  // the torso's near face through the elbow of that choice, the person facing the robot
  cg::ChainPoses poses;
  cg::chainPoses(panda(), free_planning.objectPlan().q_target, poses);
  const control::Vector3 elbow = poses.oMb[4].translation();
  control::Isometry torso = control::Isometry::Identity();
  torso.linear() = Eigen::AngleAxisd(M_PI, control::Vector3::UnitZ()).toRotationMatrix();  // facing -x
  torso.translation() = elbow + control::Vector3(0.5 * control::PersonTrunk{}.torso_size.x(), 0.0, 0.0) -
                        control::Vector3(0.0, 0.0, control::PersonTrunk{}.torso_centre);
  std::vector<cg::ObstacleCapsule> world;
  for (cg::ObstacleCapsule c : s.trunk) {
    c.a = torso * c.a;
    c.b = torso * c.b;
    c.keep_arm = s.keeps.trunk.arm;
    c.keep_gripper = s.keeps.trunk.gripper;
    world.push_back(c);
  }
  const double floor = 0.0;  // beyond what the constraints keep
  ASSERT_LT(cg::personBodyClearance(panda(), poses, world.data(), static_cast<int>(world.size())), floor);

  GraspPlanning planning(panda(), s);
  planning.update(offered(0.1, at), readyConfiguration(), false, &torso);
  int feasible = 0;
  for (const cg::CandidateEvaluation& e : planning.objectSelector().evaluations()) {
    if (!e.feasible) continue;
    ++feasible;
    cg::chainPoses(panda(), e.q_grasp, poses);
    EXPECT_GE(cg::personBodyClearance(panda(), poses, world.data(), static_cast<int>(world.size())), floor);
  }
  EXPECT_GT(feasible, 0);  // the arm reaches the bottle another way
  ASSERT_TRUE(planning.objectPlan().valid);
  cg::chainPoses(panda(), planning.objectPlan().q_target, poses);
  EXPECT_GE(cg::personBodyClearance(panda(), poses, world.data(), static_cast<int>(world.size())), floor);
}
}  // namespace
}  // namespace handover::runtime

namespace handover::runtime {
namespace {
// what the planner keeps from the person is what the shipped collision rules keep
TEST(GraspPlanning, KeepsWhatTheShippedCollisionRulesKeepFromThePerson) {
  const control::CollisionConfig cfg = control::loadCollisionConfig(control::defaultCollisionConfigPath());
  const control::CollisionModel model = control::buildCollisionModel(panda(), cfg);
  const PersonKeeps k = personKeeps(model);
  const double budget = cfg.sensing_error.budget();
  ASSERT_GT(budget, 0.0);
  // the arm keeps the person margin, the sensing budget and the default sDist from every part
  const double arm = cfg.person.margin + budget + cfg.defaults.s_dist;
  EXPECT_NEAR(k.hand.arm, arm, 1e-12);
  EXPECT_NEAR(k.forearm.arm, arm, 1e-12);
  EXPECT_NEAR(k.upper_arm.arm, arm, 1e-12);
  EXPECT_NEAR(k.trunk.arm, arm, 1e-12);
  EXPECT_NEAR(k.trunk.gripper, arm, 1e-12);
  EXPECT_NEAR(k.upper_arm.gripper, arm, 1e-12);
  // the gripper comes nearer the forearm that rises from the hand (its own rule)
  const auto rule = std::find_if(cfg.pairs.begin(), cfg.pairs.end(),
                                 [](const control::PairRule& r) { return r.name == "person_forearm_gripper"; });
  ASSERT_NE(rule, cfg.pairs.end());
  EXPECT_NEAR(k.forearm.gripper, rule->margin + budget + rule->damper.s_dist, 1e-12);
  EXPECT_LT(k.forearm.gripper, k.forearm.arm);
  // the wrist and the gripper keep the object rule's sDist from the object in the hand
  const auto object = std::find_if(cfg.pairs.begin(), cfg.pairs.end(),
                                   [](const control::PairRule& r) { return r.name == "object_gripper"; });
  ASSERT_NE(object, cfg.pairs.end());
  EXPECT_NEAR(k.object.gripper, object->margin + object->damper.s_dist, 1e-12);
  EXPECT_NEAR(k.object.arm, object->margin + object->damper.s_dist, 1e-12);
  EXPECT_GT(k.object.gripper, 0.0);
  // while the fingers share the object (a take's grasp): the gripper keeps the sharing rule's sDist
  // from the person's arm, no sensing budget; the arm and the trunk keep what they always keep
  const auto sharing = std::find_if(cfg.pairs.begin(), cfg.pairs.end(),
                                    [](const control::PairRule& r) { return r.name == "person_arm_gripper_sharing"; });
  ASSERT_NE(sharing, cfg.pairs.end());
  EXPECT_NEAR(k.forearm.gripper_sharing, sharing->margin + sharing->damper.s_dist, 1e-12);
  EXPECT_NEAR(k.upper_arm.gripper_sharing, sharing->margin + sharing->damper.s_dist, 1e-12);
  EXPECT_LT(k.forearm.gripper_sharing, k.forearm.gripper - budget + 1e-12);
  EXPECT_NEAR(k.forearm.arm_sharing, k.forearm.arm, 1e-12);
  EXPECT_NEAR(k.trunk.arm_sharing, k.trunk.arm, 1e-12);
  EXPECT_NEAR(k.trunk.gripper_sharing, k.trunk.gripper, 1e-12);
}

// The hand that holds the object out is, to the planner, the box the constraints see (where only the
// fingers may go), not a sphere around it: a palm 3 cm above the hand's face is clear of it.
TEST(GraspPlanning, TheHandThatHoldsTheObjectIsTheCollisionModelsHandBox) {
  GraspPlanningSettings s = bottleSettings(false);
  s.hand_radius = 0.045;
  s.hand_box_half_extents = control::Vector3(0.045, 0.04, 0.015);
  s.keeps.hand = {0.04, 0.02, 0.04, 0.002};
  control::Isometry hand = control::Isometry::Identity();
  hand.translation() = control::Vector3(0.5, 0.1, 0.2);
  hand.linear() = Eigen::AngleAxisd(0.7, control::Vector3::UnitZ()).toRotationMatrix();
  const cg::ObstacleCapsule box = holdingHandObstacle(s, hand);
  EXPECT_TRUE(box.gripper_works_here);
  EXPECT_EQ(box.box_half_extents, s.hand_box_half_extents);
  EXPECT_TRUE(box.box_axes.isApprox(hand.linear()));
  EXPECT_EQ(box.keep_arm, 0.04);
  EXPECT_EQ(box.keep_gripper_sharing, 0.002);
  // a segment across the hand 3 cm above its face (the palm of a grasp from above): outside the box
  const control::Vector3 up = hand.linear().col(2);
  const control::Vector3 p0 = hand * control::Vector3(-0.05, 0.0, 0.03), p1 = hand * control::Vector3(0.05, 0.0, 0.03);
  EXPECT_NEAR(cg::segmentBoxDistance(p0, p1, box.a, box.box_axes, box.box_half_extents), 0.015, 1e-9);
  EXPECT_GT((p0 - hand.translation()).dot(up), 0.0);
  // no box given: the sphere, which that segment is inside
  GraspPlanningSettings no_box = s;
  no_box.hand_box_half_extents.setZero();
  const cg::ObstacleCapsule sphere = holdingHandObstacle(no_box, hand);
  EXPECT_TRUE(sphere.box_half_extents.isZero());
  EXPECT_EQ(sphere.radius, 0.045);
  EXPECT_LT(cg::segmentDistance(p0, p1, sphere.a, sphere.b) - sphere.radius, 0.0);
}
TEST(GraspPlanning, AHeldObjectWaitsOutOfTheWayOfTheReceiverWhoWillReachForIt) {
  // a receiver in front and to the right, their shoulder above the table; the
  // object is to wait upright at the ready place, the person reaching for it
  GraspPlanning planning(panda(), bottleSettings(false));
  const control::Vector3 shoulder(0.88, -0.28, 0.69), place(0.44, 0.0, 0.40);
  perception::PerceptionEstimate e = offered(0.2, control::Vector3(0.72, -0.18, 0.20));
  e.human.upper_arm.translation() = shoulder;
  e.object.holder = perception::ObjectHolder::Robot;
  planning.update(e, readyConfiguration(), true);
  const control::Isometry object_in_tcp = bottleSettings(false).object_grasps[0].placement.inverse();
  const double stop = 0.03;  // the bottle's radius: their hand stops at its side
  // their way to it, as far as their hand goes: the palm and the arm keep out, the fingers hold the object at its end
  cg::ObstacleCapsule reach;
  reach.a = shoulder;
  reach.b = place + (shoulder - place).normalized() * (stop + GraspPlanningSettings{}.hand_radius);
  reach.radius = GraspPlanningSettings{}.hand_radius;
  reach.gripper_works_here = true;
  auto crossing = [&](const fsm::ArmPlacement& p) {
    cg::ChainPoses poses;
    cg::chainPoses(panda(), p.q, poses);
    return cg::workZoneClearance(panda(), poses, &reach, 1);
  };
  const fsm::ArmPlacement blind = planning.uprightPlacement(object_in_tcp, control::Vector3::UnitZ(), place,
                                                            readyConfiguration(), 0.0);
  const fsm::ArmPlacement aware = planning.uprightPlacement(object_in_tcp, control::Vector3::UnitZ(), place,
                                                            readyConfiguration(), stop);
  ASSERT_TRUE(blind.found);
  ASSERT_TRUE(aware.found);
  EXPECT_LT(crossing(blind), 0.0);  // without them the wrist waits across their way
  EXPECT_GT(crossing(aware), 0.0);
  // still upright at the place asked for
  const control::Isometry object = tcpPose(panda(), aware.q) * object_in_tcp;
  EXPECT_GT(object.linear().col(2).z(), std::cos(10.0 * M_PI / 180.0));
  EXPECT_LT((object.translation() - place).norm(), 1e-3);
}

}  // namespace
}  // namespace handover::runtime

namespace handover::runtime {
namespace {
/// A bottle (radius 3.3 cm, 22 cm) held from the side 8 cm below its centre,
/// presented upright with its centre 5 cm above the receiver's grip point.
GraspPlanningSettings bottleHeldByItsBase(const control::Vector3& grasp_at) {
  GraspPlanningSettings s = bottleSettings(false);
  s.held_grasp = s.object_grasps.front().placement;
  s.held_grasp.translation() = grasp_at;
  s.object_shape.kind = io::ObjectShape::Kind::kCylinder;
  s.object_shape.size = control::Vector3(0.033, 0.22, 0.0);
  s.presentation_pivot = control::Vector3(0.0, 0.0, 0.05);
  s.presentation = Eigen::Translation3d(s.presentation_pivot) * s.held_grasp;  // object upright, centre at the pivot
  return s;
}

// Each presentation also comes with the object moved so that the receiver's
// grip point lies on its free part, halfway from its centre to the end away
// from the grasp; none for a grasp at the centre or an unknown shape.
TEST(GraspPlanning, PresentationsAlsoPutTheHandOnTheObjectsFreePart) {
  const GraspPlanningSettings s = bottleHeldByItsBase(control::Vector3(0.0, 0.0, -0.08));
  const std::vector<cg::GraspSpec> specs = presentationSpecs(s);
  ASSERT_EQ(specs.size(), 6u);  // upright, two tilts, and each moved
  for (std::size_t k = 3; k < 6; ++k) {
    const control::Isometry object = specs[k].placement * s.held_grasp.inverse();  // object in the hand frame
    const control::Vector3 grip_in_object = object.inverse() * control::Vector3::Zero();
    EXPECT_NEAR(grip_in_object.z(), 0.055, 1e-9) << k;  // half of the 11 cm above the centre
    EXPECT_NEAR(grip_in_object.head<2>().norm(), 0.0, 1e-9) << k;
    EXPECT_EQ(specs[k].preference, 0.0);
    // the gripper is farther from the grip point than in the declared seat
    EXPECT_GT(specs[k].placement.translation().norm(), specs[k - 3].placement.translation().norm() + 0.05) << k;
  }
  EXPECT_EQ(presentationSpecs(bottleHeldByItsBase(control::Vector3(0.0, 0.0, 0.01))).size(), 3u);
  GraspPlanningSettings unknown = s;
  unknown.object_shape = io::ObjectShape{};
  EXPECT_EQ(presentationSpecs(unknown).size(), 3u);
}

// The bottle held by its base, given: seated as declared, the gripper lies in
// the receiver's hand, and the constraints that keep it off the hand hold it
// short (the approach stopped 6 cm short until the give timed out, outsider
// s_31); the planner puts the hand on the bottle's upper part instead.
TEST(GraspPlanning, AnObjectHeldByOneEndIsPresentedWithItsOtherEndInTheHand) {
  GraspPlanningSettings s = bottleHeldByItsBase(control::Vector3(0.0, 0.0, -0.08));
  s.keeps.hand.gripper = 0.021;
  s.keeps.hand.arm = 0.04;
  s.hand_box_half_extents = control::Vector3(0.045, 0.04, 0.015);
  const control::Vector3 hand(0.58, -0.05, 0.37);
  perception::PerceptionEstimate e = offered(0.2, hand + control::Vector3(0.0, 0.0, 0.08));
  e.object.holder = perception::ObjectHolder::Robot;
  GraspPlanning planning(panda(), s);
  planning.update(e, readyConfiguration(), true);
  ASSERT_TRUE(planning.handPlan().valid);
  const control::Isometry object = planning.handPlan().target_in_observed * s.held_grasp.inverse();
  EXPECT_GT((object.inverse() * control::Vector3::Zero()).z(), 0.03) << "the hand holds the upper part";
  EXPECT_LT(presentationShortfall(s, e, planning.handPlan().q_target), 0.005);
}
}  // namespace
}  // namespace handover::runtime

namespace handover::runtime {
namespace {

using cg::testing::panda;
using cg::testing::readyConfiguration;
using cg::testing::shippedConfig;

TEST(GraspPlanning, TheHeldObjectObstacleIsInscribedInItsShape) {
  control::Isometry X = control::Isometry::Identity();
  X.linear() = Eigen::AngleAxisd(0.4, control::Vector3(1.0, -2.0, 0.3).normalized()).toRotationMatrix();
  X.translation() = control::Vector3(0.5, -0.1, 0.3);
  const PersonKeeps::Keep keep{0.004, 0.006};
  io::ObjectShape shape;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  for (const auto& [kind, size] : {std::pair{io::ObjectShape::Kind::kCylinder, control::Vector3(0.03, 0.60, 0.0)},
                                   std::pair{io::ObjectShape::Kind::kCylinder, control::Vector3(0.10, 0.02, 0.0)},
                                   std::pair{io::ObjectShape::Kind::kBox, control::Vector3(0.05, 0.07, 0.20)},
                                   std::pair{io::ObjectShape::Kind::kSphere, control::Vector3(0.035, 0.0, 0.0)}}) {
    shape.kind = kind;
    shape.size = size;
    const cg::ObstacleCapsule o = heldObjectObstacle(shape, X, keep);
    EXPECT_TRUE(o.held_object);
    EXPECT_EQ(o.keep_arm, 0.004);
    EXPECT_EQ(o.keep_gripper, 0.006);
    // signed distance (m) of a world point to the obstacle
    auto toObstacle = [&](const control::Vector3& w) {
      return (o.box_half_extents.isZero() ? cg::segmentDistance(w, w, o.a, o.b)
                                          : cg::segmentBoxDistance(w, w, o.a, o.box_axes, o.box_half_extents)) -
             o.radius;
    };
    // no point of the obstacle lies outside the shape; the shape's centre lies in the obstacle
    int inside = 0;
    for (int i = 0; i < 20000; ++i) {
      const control::Vector3 p(u(rng), u(rng), u(rng));
      if (toObstacle(X * p) > 0.0) continue;
      ++inside;
      EXPECT_LE(io::signedDistance(shape, p), 1e-9) << p.transpose();
    }
    EXPECT_GT(inside, 0);
    EXPECT_LE(toObstacle(X.translation()), 0.0);
  }
}

// A 60 cm tube held tilted toward the robot by 30 degrees (outsider o_14),
// declared with two grasps, one from above 20 cm up its axis: the pre-grasp
// 8 cm back along that approach put the gripper on the tube's upper end, and
// the constraint that keeps the gripper off the object held it there for
// 10 s until the approach gave up.
TEST(GraspPlanning, NoPreGraspPutsTheGripperInsideTheObjectInTheHand) {
  GraspPlanningSettings s;
  s.config = shippedConfig();
  cg::GraspSpec declared;
  declared.placement.translation() = control::Vector3(0.0, 0.0, 0.15);
  declared.placement.linear() = (Eigen::AngleAxisd(M_PI, control::Vector3::UnitZ()) *
                                 Eigen::AngleAxisd(1.0472, control::Vector3::UnitY()) *
                                 Eigen::AngleAxisd(M_PI, control::Vector3::UnitX())).toRotationMatrix();
  declared.has_free_axis = true;
  declared.preference = s.config.declared_preference;
  s.object_grasps.push_back(declared);
  // and from above, 20 cm up the tube: the tube's last 10 cm run up between the fingers
  cg::GraspSpec high = declared;
  high.placement.translation() = control::Vector3(0.0, 0.0, 0.20);
  high.placement.linear() = (Eigen::AngleAxisd(M_PI, control::Vector3::UnitZ()) *
                             Eigen::AngleAxisd(-0.5236, control::Vector3::UnitY()) *
                             Eigen::AngleAxisd(M_PI, control::Vector3::UnitX())).toRotationMatrix();
  s.object_grasps.push_back(high);
  s.object_shape.kind = io::ObjectShape::Kind::kCylinder;
  s.object_shape.size = control::Vector3(0.03, 0.60, 0.0);
  s.keeps.object = {0.005, 0.005};
  perception::PerceptionEstimate e = offered(0.1, control::Vector3(0.505, -0.05, 0.35));
  e.object.pose.linear() = Eigen::AngleAxisd(-0.5236, control::Vector3::UnitY()).toRotationMatrix();
  const cg::ObstacleCapsule tube = heldObjectObstacle(s.object_shape, e.object.pose, s.keeps.object);
  auto preGraspClearance = [&](const control::Vector7& q_pre) {
    cg::ChainPoses poses;
    cg::chainPoses(panda(), q_pre, poses);
    return cg::heldObjectClearance(panda(), poses, &tube, 1);
  };
  // the premise: blind to the tube, the planner finds turns about its axis that line up inside it
  GraspPlanningSettings blind = s;
  blind.object_shape = io::ObjectShape{};
  GraspPlanning without(panda(), blind);
  without.update(e, readyConfiguration(), false);
  int inside = 0;
  for (const cg::CandidateEvaluation& c : without.objectSelector().evaluations())
    inside += c.feasible && preGraspClearance(c.q_pre_grasp) < 0.0;
  ASSERT_GT(inside, 0);
  // knowing it, no candidate does, and one in front of it is chosen
  GraspPlanning planning(panda(), s);
  planning.update(e, readyConfiguration(), false);
  ASSERT_TRUE(planning.objectPlan().valid);
  int feasible = 0;
  for (const cg::CandidateEvaluation& c : planning.objectSelector().evaluations()) {
    if (!c.feasible) continue;
    ++feasible;
    EXPECT_GE(preGraspClearance(c.q_pre_grasp), 0.0);
  }
  EXPECT_GT(feasible, 0);
  EXPECT_GE(preGraspClearance(planning.objectPlan().q_pre), 0.0);
}

}  // namespace
}  // namespace handover::runtime
