// The states and the grasp planner (fsm/handover/grasp_plan.hpp): Approach
// follows the planner's choice and its IK configuration, Grasp commits to the
// choice it started with, the payload's centre of mass follows the grasp
// closed on, and a held object is carried upright in joint space.
#include <gtest/gtest.h>

#include "fsm/handover/held_object_goal.hpp"
#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {

const Vector3 kMeet(0.55, 0.0, 0.30);

/// A grasp from the side: approach along the object's x axis.
TrackingPlan sidePlan(int index, double q_mark) {
  TrackingPlan p;
  p.valid = true;
  p.index = index;
  p.target_in_observed.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  p.target_in_observed.translation() = Vector3(0.0, 0.0, 0.001 * index);  // within the toy gripper's reach
  p.q_target = Vector7::Constant(q_mark);
  p.q_pre = Vector7::Constant(q_mark + 0.5);
  return p;
}

/// Records every placement request and answers with a fixed one.
struct FakePlanner : PlannerInterface {
  int calls = 0;
  Isometry last_object_in_tcp = Isometry::Identity();
  ArmPlacement answer;
  ArmPlacement uprightPlacement(const Isometry& object_in_tcp, const Vector3&, const Vector3&,
                                const Vector7&) override {
    ++calls;
    last_object_in_tcp = object_in_tcp;
    return answer;
  }
};

/// The person offers, lets go once gripped for 0.1 s; runs until Retract has started.
void takeUntilRetract(Rig& rig) {
  rig.world.moveHand(kMeet, 0.5);
  auto gripped_since = std::make_shared<double>(-1.0);
  rig.person = [gripped_since](World& w) {
    if (!w.robot_grip) return;
    if (*gripped_since < 0) *gripped_since = w.time;
    if (w.time - *gripped_since >= 0.1 && w.person_holds) {
      w.person_holds = false;
      w.moveHand(w.hand + Vector3(0.3, 0.0, 0.0), 0.5);  // and withdraws
    }
  };
  ASSERT_TRUE(rig.runUntilState("Retract", 20.0)) << rig.fsm->activePath();
  rig.step();
}

/// The person offers with `plan` reported by the planner; runs until Approach has started.
void offerUntilApproach(Rig& rig, const TrackingPlan& plan) {
  rig.world.object_plan = plan;
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("Approach", 5.0));
  rig.step();
}

bool same(const Isometry& a, const Isometry& b) { return a.isApprox(b, 1e-12); }

TEST(PlannedTargets, ApproachTracksThePlanExactlyWithItsConfiguration) {
  Rig rig;
  offerUntilApproach(rig, sidePlan(3, 0.1));
  EXPECT_TRUE(rig.ctl.offset_planned);
  // backed off along the approach axis by the state's standoff
  const Isometry& plan = rig.world.object_plan.target_in_observed;
  EXPECT_TRUE(rig.ctl.offset.linear().isApprox(plan.linear()));
  EXPECT_GT((rig.ctl.offset.translation() - plan.translation()).norm(), 0.05);
  EXPECT_TRUE(rig.ctl.posture_active);
  EXPECT_TRUE(rig.ctl.posture.isApprox(rig.world.object_plan.q_pre));  // pre-grasp configuration
}

TEST(PlannedTargets, ApproachFollowsASwitchAndGraspCommits) {
  Rig rig;
  offerUntilApproach(rig, sidePlan(3, 0.1));
  // the planner switches while the robot still approaches: the target follows
  rig.world.object_plan = sidePlan(4, 0.2);
  rig.step();
  EXPECT_TRUE(rig.ctl.posture.isApprox(rig.world.object_plan.q_pre));
  EXPECT_EQ(rig.fsm->context().grasp.index, 4);
  ASSERT_TRUE(rig.runUntilState("Grasp", 10.0)) << rig.fsm->activePath();
  rig.step();
  EXPECT_TRUE(same(rig.ctl.offset, rig.world.object_plan.target_in_observed));  // no standoff: the grasp itself
  EXPECT_TRUE(rig.ctl.posture.isApprox(rig.world.object_plan.q_target));
  // a switch now would swing the open fingers around the object: ignored
  const Isometry committed = rig.ctl.offset;
  rig.world.object_plan = sidePlan(5, 0.3);
  rig.runFor(0.05);
  EXPECT_TRUE(same(rig.ctl.offset, committed));
  EXPECT_EQ(rig.fsm->context().grasp.index, 4);
}

TEST(PlannedTargets, WithoutAPlanTheDeclaredGraspIsLeftToTheController) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("Approach", 5.0));
  rig.step();
  EXPECT_FALSE(rig.ctl.offset_planned);
  EXPECT_FALSE(rig.ctl.posture_active);
}

TEST(PlannedTargets, PayloadCentreOfMassFollowsTheGraspClosedOn) {
  RecordingController ctl;
  ObjectInfo obj;
  obj.mass = 0.4;
  obj.grasp_in_object.translation() = Vector3(0.0, 0.0, 0.05);  // declared: 5 cm above the centre
  obj.com_in_tcp = obj.grasp_in_object.inverse() * Vector3::Zero();
  auto fsm = HandoverFsm::fromFile(HandoverFsm::defaultConfigPath(), ctl, obj);
  const HandoverContext& ctx = fsm->context();
  EXPECT_TRUE(ctx.comInTcp().isApprox(Vector3(0.0, 0.0, -0.05)));
  // a planned side grasp through the centre: the centre of mass is at the TCP
  const_cast<HandoverContext&>(ctx).grasp.adopt(sidePlan(0, 0.0));
  EXPECT_LT((ctx.comInTcp() - sidePlan(0, 0.0).target_in_observed.inverse().translation()).norm(), 1e-12);
}

TEST(PlannedTargets, HeldObjectIsCarriedUprightInJointSpace) {
  Rig rig;
  FakePlanner planner;
  planner.answer.found = true;
  planner.answer.q = Vector7::Constant(0.7);
  planner.answer.tcp.translation() = Vector3(0.35, 0.1, 0.45);
  rig.fsm->setPlanner(&planner);
  rig.world.object_plan = sidePlan(2, 0.1);
  takeUntilRetract(rig);
  EXPECT_EQ(planner.calls, 1);
  // asked with the grasp closed on (the plan's), not the declared one
  EXPECT_TRUE(planner.last_object_in_tcp.isApprox(rig.world.object_plan.target_in_observed.inverse()));
  EXPECT_FALSE(rig.ctl.pose_active);   // no TCP pose task: the joints move
  EXPECT_TRUE(rig.ctl.posture_active);
  EXPECT_TRUE(rig.ctl.posture.isApprox(planner.answer.q));
}

TEST(PlannedTargets, NoPlacementFallsBackToTheNamedPose) {
  Rig rig;
  FakePlanner planner;  // answers "not found"
  rig.fsm->setPlanner(&planner);
  takeUntilRetract(rig);
  EXPECT_EQ(planner.calls, 1);
  EXPECT_TRUE(rig.ctl.pose_active);
  EXPECT_TRUE(same(rig.ctl.pose, rig.fsm->params().stow_pose) ||
              (rig.ctl.pose.translation() - rig.fsm->params().stow_pose.translation()).norm() < 1e-9);
}

TEST(PlannedTargets, AHeldObjectKeepsTheWayUpItWasHandedOver) {
  // a bottle standing, tilted 20 degrees: its z axis
  const Eigen::Matrix3d tilted = Eigen::AngleAxisd(0.35, Vector3::UnitX()).toRotationMatrix();
  EXPECT_TRUE(handedUpAxis(tilted).isApprox(Vector3::UnitZ()));
  // a baton held lying, its y axis pointing down: -y is up
  const Eigen::Matrix3d lying = Eigen::AngleAxisd(-M_PI / 2, Vector3::UnitX()).toRotationMatrix();
  EXPECT_TRUE(handedUpAxis(lying).isApprox(-Vector3::UnitY())) << handedUpAxis(lying).transpose();
  // upside down
  const Eigen::Matrix3d flipped = Eigen::AngleAxisd(M_PI, Vector3::UnitY()).toRotationMatrix();
  EXPECT_TRUE(handedUpAxis(flipped).isApprox(-Vector3::UnitZ()));
}

}  // namespace
}  // namespace handover::fsm::test
