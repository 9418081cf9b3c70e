// The states and the grasp planner (fsm/handover/grasp_plan.hpp): Approach
// follows the planner's choice and its IK configuration, Grasp commits to the
// choice it started with, the payload's centre of mass follows the grasp
// closed on, and a held object is carried upright in joint space, with the
// placement asked for in the step and searched in the planning stage.
#include <gtest/gtest.h>

#include "fsm/handover/held_object_goal.hpp"
#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {


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
  Vector3 last_up_axis = Vector3::Zero();
  Vector3 last_position = Vector3::Zero();
  double last_receiver_stop = -1.0;
  ArmPlacement answer;
  ArmPlacement uprightPlacement(const Isometry& object_in_tcp, const Vector3& up_axis, const Vector3& position,
                                const Vector7&, double receiver_stop) override {
    ++calls;
    last_object_in_tcp = object_in_tcp;
    last_up_axis = up_axis;
    last_position = position;
    last_receiver_stop = receiver_stop;
    return answer;
  }
};

/// A placement found: joints all at 0.7 rad, the TCP at (0.35, 0.1, 0.45).
ArmPlacement uprightAnswer() {
  ArmPlacement a;
  a.found = true;
  a.q = Vector7::Constant(0.7);
  a.tcp.translation() = Vector3(0.35, 0.1, 0.45);
  return a;
}

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
  // past the lift-off: the carry has posted its request (and, with the
  // planning stage on, the state has taken the answer)
  ASSERT_TRUE(rig.runUntil([&] { return rig.fsm->context().carry.request().id > 0; }, 2.0));
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
  // the slide goes on from the approach's standoff (at most 8 cm: 0.3 s at 0.4 m/s, 4 m/s^2)
  rig.runUntil([&] { return rig.fsm->context().tracking_standoff == 0.0; }, 0.5);
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

// The arm held short of a planned target by a joint at its limit (the toy arm
// is stuck) with the object at rest: after the approach's
// stall_time without progress it moves in joint space to the planner's
// configuration for its target (tracking off, the posture task alone), and
// tracks again once that move is over. Without progress owed (the object still
// brought in) nothing happens.
TEST(PlannedTargets, AStalledApproachGoesOnInJointSpaceToThePlannersConfiguration) {
  Rig rig;
  rig.world.arm_stuck = true;
  rig.world.joint_limit_margin = 0.04;  // rad: a joint at its limit holds it
  offerUntilApproach(rig, sidePlan(3, 0.1));
  ASSERT_TRUE(rig.runUntil([&] { return rig.world.hand_vel.norm() == 0.0; }, 5.0));  // the offer rests
  const double rested = rig.world.time;
  ASSERT_TRUE(rig.runUntil([&] { return !rig.ctl.tracking; }, 3.0)) << rig.fsm->activePath();
  const double stall = rig.world.time - rested;
  EXPECT_GT(stall, 0.3);
  EXPECT_LT(stall, 1.5);
  EXPECT_TRUE(Rig::endsWith(rig.fsm->activePath(), "/Approach")) << rig.fsm->activePath();
  EXPECT_FALSE(rig.ctl.pose_active);
  ASSERT_TRUE(rig.ctl.posture_active);
  // the configuration for the target it tracked: the pre-grasp while backed off, the grasp once slid in
  const TrackingPlan& plan = rig.world.object_plan;
  const Vector7& goal = rig.fsm->context().tracking_standoff > 0.0 ? plan.q_pre : plan.q_target;
  EXPECT_TRUE(rig.ctl.posture.isApprox(goal));
  // the toy arm's joints never get there: the move ends after its time, tracking the plan again
  const double moving_since = rig.world.time;
  ASSERT_TRUE(rig.runUntil([&] { return rig.ctl.tracking; }, 5.0)) << rig.fsm->activePath();
  EXPECT_NEAR(rig.world.time - moving_since, 2.0, 0.01);  // 2 stall_time + 1 s
  EXPECT_TRUE(rig.ctl.offset_planned);
}

// Held short with every joint free of its limits, something else holds the
// arm (the object or the person in the way): a move in joint space would go
// through them, so the approach keeps tracking.
TEST(PlannedTargets, AnApproachHeldShortWithItsJointsFreeKeepsTracking) {
  Rig rig;
  rig.world.arm_stuck = true;
  rig.world.joint_limit_margin = 0.3;
  offerUntilApproach(rig, sidePlan(3, 0.1));
  const int off_before = rig.ctl.count("tracking off");
  rig.runFor(4.0);
  EXPECT_TRUE(Rig::endsWith(rig.fsm->activePath(), "/Approach")) << rig.fsm->activePath();
  EXPECT_TRUE(rig.ctl.tracking);
  EXPECT_EQ(rig.ctl.count("tracking off"), off_before);
}

// Held short beside the object it lines up on (the TCP past the funnel's mouth
// and 10 cm off the approach line, the palm against the object: g881_00174)
// with every joint free: after stall_time without progress the approach lines
// up from in front of the object again, as far back along the approach axis as
// the TCP is off the line, tracking on; back on the line, the funnel goes on.
TEST(PlannedTargets, AnApproachStalledBesideTheObjectLinesUpInFrontOfItAgain) {
  Rig rig;
  rig.world.joint_limit_margin = 0.3;  // rad: no joint at its limit
  const TrackingPlan plan = sidePlan(3, 0.1);  // the approach axis along world +x
  offerUntilApproach(rig, plan);
  ASSERT_TRUE(rig.runUntil([&] { return rig.world.hand_vel.norm() == 0.0; }, 5.0));  // the offer rests
  const HandoverContext& ctx = rig.fsm->context();
  const double mouth = ctx.tracking_standoff;
  ASSERT_GT(mouth, 0.0);
  // the gripper stands beside the object: at its depth along the axis, 10 cm across it, and stays
  const Vector3 grasp = (rig.world.objectPose() * plan.target_in_observed).translation();
  rig.world.tcp.translation() = grasp + Vector3(0.0, 0.10, 0.0);
  rig.world.arm_stuck = true;
  const double stuck = rig.world.time;
  ASSERT_TRUE(rig.runUntil([&] { return ctx.tracking_standoff > mouth + 0.09; }, 3.0)) << ctx.tracking_standoff;
  EXPECT_GT(rig.world.time - stuck, 0.4);  // after stall_time, not at once
  EXPECT_TRUE(Rig::endsWith(rig.fsm->activePath(), "/Approach")) << rig.fsm->activePath();
  EXPECT_TRUE(rig.ctl.tracking);  // no move in joint space: it would go through the object
  rig.runFor(0.5);
  EXPECT_LT(ctx.tracking_standoff, mouth + 0.10 + 1e-6);  // as far back as it is off the line
  // free again, it comes back onto the line from in front, and the funnel takes over
  rig.world.arm_stuck = false;
  ASSERT_TRUE(rig.runUntil([&] { return ctx.tracking_standoff <= mouth + 1e-6; }, 3.0)) << ctx.tracking_standoff;
  const Vector3 tcp = rig.world.tcp.translation() - grasp;
  EXPECT_LT(tcp.x(), -mouth + 0.02);  // in front of the object along the axis, not beside it
}

// Held short at the object's depth but within near_distance of the approach line (the funnel's own slide
// pushed by the object), or beside it with a joint at its limit: no detour.
TEST(PlannedTargets, OnlyAGripperBesideTheObjectWithItsJointsFreeDetours) {
  for (const bool at_limit : {false, true}) {
    Rig rig;
    rig.world.joint_limit_margin = at_limit ? 0.04 : 0.3;
    const TrackingPlan plan = sidePlan(3, 0.1);
    offerUntilApproach(rig, plan);
    ASSERT_TRUE(rig.runUntil([&] { return rig.world.hand_vel.norm() == 0.0; }, 5.0));
    const HandoverContext& ctx = rig.fsm->context();
    const double mouth = ctx.tracking_standoff;
    const Vector3 grasp = (rig.world.objectPose() * plan.target_in_observed).translation();
    rig.world.tcp.translation() = grasp + Vector3(0.0, at_limit ? 0.10 : 0.01, 0.0);
    rig.world.arm_stuck = true;
    rig.runFor(2.0);
    EXPECT_LE(ctx.tracking_standoff, mouth + 1e-6) << "at limit " << at_limit;
  }
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

/// The carry's joint-space move (timed, params.carry) ends at `q`: its
/// reference heads there at once (velocity along q - reference) and reaches
/// it at rest within `seconds`.
::testing::AssertionResult carriesTo(Rig& rig, const Vector7& q, double seconds = 5.0) {
  const Vector7 heading = q - rig.ctl.posture;
  if (heading.norm() > 1e-9 && rig.ctl.posture_velocity.norm() > 0.0 &&
      rig.ctl.posture_velocity.normalized().dot(heading.normalized()) < 1.0 - 1e-9)
    return ::testing::AssertionFailure() << "the reference moves elsewhere";
  const bool reached = rig.runUntil(
      [&] { return rig.ctl.posture.isApprox(q, 1e-9) && rig.ctl.posture_velocity.norm() < 1e-12; }, seconds);
  if (!reached) return ::testing::AssertionFailure() << "the reference is at " << rig.ctl.posture.transpose();
  return ::testing::AssertionSuccess();
}

TEST(PlannedTargets, HeldObjectIsCarriedUprightInJointSpace) {
  Rig rig;
  FakePlanner planner;
  planner.answer = uprightAnswer();
  rig.fsm->setPlanner(&planner);
  rig.world.object_plan = sidePlan(2, 0.1);
  takeUntilRetract(rig);
  EXPECT_EQ(planner.calls, 1);
  EXPECT_EQ(planner.last_receiver_stop, 0.0);  // the stow: nobody reaches for the object there
  // asked with the grasp closed on (the plan's), not the declared one
  EXPECT_TRUE(planner.last_object_in_tcp.isApprox(rig.world.object_plan.target_in_observed.inverse()));
  EXPECT_FALSE(rig.ctl.pose_active);   // no TCP pose task: the joints move
  EXPECT_TRUE(rig.ctl.posture_active);
  EXPECT_TRUE(carriesTo(rig, planner.answer.q));
}

// With params.carry.joint_speed set, the carry to the placement is a timed
// joint-space move: a cruise profile whose fastest joint cruises at
// joint_speed (0.8 rad/s here) between smooth ramps, its velocity fed
// forward, ending at the placement's configuration at rest: sooner than a
// minimum-jerk move held to the same peak (1.875 x travel / speed), never
// sooner than travel / speed.
TEST(PlannedTargets, TheCarryIsATimedMoveAtTheCarrysJointSpeed) {
  Rig rig(false, false, io::ObjectShape{}, [](YAML::Node& doc) { doc["params"]["carry"]["joint_speed"] = 0.8; });
  FakePlanner planner;
  planner.answer = uprightAnswer();  // 0.7 rad on every joint from the toy's q = 0
  rig.fsm->setPlanner(&planner);
  rig.world.object_plan = sidePlan(2, 0.1);
  takeUntilRetract(rig);
  ASSERT_TRUE(rig.runUntil([&] { return rig.ctl.posture_active; }, 3.0));
  const double speed = rig.fsm->params().carry_joint_speed;
  ASSERT_GT(speed, 0.0);
  const double start = rig.world.time;
  double peak = 0.0;
  ASSERT_TRUE(rig.runUntil(
      [&] {
        peak = std::max(peak, rig.ctl.posture_velocity.cwiseAbs().maxCoeff());
        return rig.ctl.posture.isApprox(planner.answer.q, 1e-12);
      },
      5.0));
  EXPECT_LT(rig.world.time - start, 1.875 * 0.7 / speed);
  EXPECT_GT(rig.world.time - start, 0.7 / speed);
  EXPECT_NEAR(peak, speed, 0.01 * speed);
}

TEST(PlannedTargets, TheCarrySearchRunsOutsideTheStepAndIsAdoptedOnceAnswered) {
  Rig rig;
  rig.plan_stage = false;  // this test answers
  FakePlanner planner;
  planner.answer = uprightAnswer();
  rig.fsm->setPlanner(&planner);
  rig.world.object_plan = sidePlan(2, 0.1);
  takeUntilRetract(rig);
  const HandoverContext& ctx = rig.fsm->context();
  const Isometry& stow = rig.fsm->params().stow_pose;
  // Retract asked in its step; no step searches
  EXPECT_EQ(planner.calls, 0);
  ASSERT_TRUE(ctx.carry.pending());
  EXPECT_TRUE(ctx.carry.request().object_in_tcp.isApprox(rig.world.object_plan.target_in_observed.inverse()));
  // where the named pose it sends (the stow pose turned about the vertical: keep_yaw) puts the object
  EXPECT_TRUE(rig.ctl.pose_active);
  EXPECT_TRUE(ctx.carry.request().object_position.isApprox((rig.ctl.pose * ctx.objectInTcp()).translation()));
  // meanwhile the named pose, and Retract does not finish on it: the
  // placement may lie elsewhere (the toy TCP reaches the stow pose and settles)
  rig.runFor(3.0);
  EXPECT_EQ(planner.calls, 0);
  EXPECT_TRUE(rig.ctl.pose_active);
  EXPECT_LT((rig.ctl.pose.translation() - stow.translation()).norm(), 1e-9);
  EXPECT_LT((rig.world.tcp.translation() - stow.translation()).norm(), 0.01);
  EXPECT_TRUE(Rig::endsWith(rig.fsm->activePath(), "Retract")) << rig.fsm->activePath();
  // the planning stage answers; the state takes the answer in its next run
  rig.fsm->plan();
  EXPECT_EQ(planner.calls, 1);
  EXPECT_FALSE(ctx.carry.pending());
  EXPECT_TRUE(rig.ctl.pose_active);
  rig.step();
  EXPECT_FALSE(rig.ctl.pose_active);
  EXPECT_TRUE(rig.ctl.posture_active);
  rig.step();
  EXPECT_TRUE(carriesTo(rig, planner.answer.q));
  // one search per request
  rig.fsm->plan();
  rig.step();
  EXPECT_EQ(planner.calls, 1);
}

TEST(PlannedTargets, AnAnswerToAnEarlierStatesRequestIsNeverAdopted) {
  Rig rig(true);  // a give: HoldReady carries the object to the ready pose
  rig.plan_stage = false;
  FakePlanner planner;
  planner.answer.found = true;
  planner.answer.q = Vector7::Constant(0.7);
  rig.fsm->setPlanner(&planner);
  ASSERT_TRUE(rig.runUntilState("HoldReady", 1.0)) << rig.fsm->activePath();
  const HandoverContext& ctx = rig.fsm->context();
  const int first = ctx.carry.request().id;
  rig.fsm->plan();  // answered...
  ASSERT_EQ(planner.calls, 1);
  ASSERT_NE(ctx.carry.answerTo(first), nullptr);
  // ...but the person comes too close before HoldReady runs again
  rig.world.arm_distance = 0.02;
  rig.step();
  ASSERT_TRUE(Rig::endsWith(rig.fsm->activePath(), "SafetyStop")) << rig.fsm->activePath();
  // the person steps back: the machine starts over, and HoldReady asks again
  rig.world.arm_distance = 1.0;
  ASSERT_TRUE(rig.runUntilState("HoldReady", 2.0)) << rig.fsm->activePath();
  EXPECT_GT(ctx.carry.request().id, first);
  EXPECT_TRUE(ctx.carry.pending());
  rig.runFor(0.02);
  // the first answer was for the first HoldReady: the ready pose stays
  EXPECT_TRUE(rig.ctl.pose_active);
  EXPECT_TRUE(same(rig.ctl.pose, rig.fsm->params().ready_pose));
  EXPECT_FALSE(rig.ctl.posture_active && rig.ctl.posture.isApprox(Vector7::Constant(0.7)));
  // its own answer it takes
  planner.answer.q = Vector7::Constant(-0.4);
  rig.fsm->plan();
  rig.step();
  EXPECT_EQ(planner.calls, 2);
  EXPECT_FALSE(rig.ctl.pose_active);
  rig.step();
  EXPECT_TRUE(carriesTo(rig, Vector7::Constant(-0.4)));
}

TEST(PlannedTargets, ARequestLeftByAnEndedStateIsNotSearched) {
  Rig rig(true);
  rig.plan_stage = false;
  FakePlanner planner;
  rig.fsm->setPlanner(&planner);
  ASSERT_TRUE(rig.runUntilState("HoldReady", 1.0)) << rig.fsm->activePath();
  EXPECT_TRUE(rig.fsm->context().carry.pending());
  rig.world.arm_distance = 0.02;  // a safety stop ends HoldReady before any answer
  rig.step();
  ASSERT_TRUE(Rig::endsWith(rig.fsm->activePath(), "SafetyStop")) << rig.fsm->activePath();
  EXPECT_FALSE(rig.fsm->context().carry.pending());
  rig.fsm->plan();
  EXPECT_EQ(planner.calls, 0);
}

TEST(PlannedTargets, WithoutAPlannerTheCarryAsksNothing) {
  Rig rig(true);
  ASSERT_TRUE(rig.runUntilState("HoldReady", 1.0)) << rig.fsm->activePath();
  rig.step();
  EXPECT_FALSE(rig.fsm->context().carry.pending());
  EXPECT_TRUE(rig.ctl.pose_active);
  EXPECT_TRUE(same(rig.ctl.pose, rig.fsm->params().ready_pose));
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

TEST(PlannedTargets, AnEmptyGripperAlsoMovesInJointSpaceToTheNamedPoseWithItsTurnFree) {
  Rig rig;
  FakePlanner planner;
  planner.answer = uprightAnswer();
  rig.fsm->setPlanner(&planner);
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("Approach", 5.0)) << rig.fsm->activePath();
  rig.world.moveHand(kAway, 0.8);  // the person changes their mind: Retreat, gripper empty
  ASSERT_TRUE(rig.runUntilState("Retreat", 3.0)) << rig.fsm->activePath();
  rig.runFor(0.01);
  ASSERT_EQ(planner.calls, 1);
  // the TCP itself is placed: at the safe pose's position, the TCP axis that
  // points up there kept up (gripper down: -z), its turn left to the search
  const Isometry& safe = rig.fsm->params().safe_pose;
  EXPECT_TRUE(planner.last_object_in_tcp.isApprox(Isometry::Identity()));
  EXPECT_TRUE(planner.last_position.isApprox(safe.translation()));
  EXPECT_TRUE(planner.last_up_axis.isApprox(handedUpAxis(Eigen::Matrix3d(safe.linear()))));
  EXPECT_FALSE(rig.ctl.pose_active);
  EXPECT_TRUE(carriesTo(rig, planner.answer.q));
}

TEST(PlannedTargets, AGiveAsksWhereToWaitOnceItSeesTheReceiverAndOutOfTheirWay) {
  Rig rig(true);
  rig.plan_stage = false;
  FakePlanner planner;
  rig.fsm->setPlanner(&planner);
  rig.world.dropout = true;  // nobody seen yet
  ASSERT_TRUE(rig.runUntilState("HoldReady", 1.0)) << rig.fsm->activePath();
  rig.runFor(0.05);
  const HandoverContext& ctx = rig.fsm->context();
  // heading for the ready pose meanwhile, no placement asked for without the person it keeps clear of
  EXPECT_FALSE(ctx.carry.pending());
  EXPECT_TRUE(rig.ctl.pose_active);
  EXPECT_TRUE(same(rig.ctl.pose, rig.fsm->params().ready_pose));
  rig.world.dropout = false;
  rig.step();
  ASSERT_TRUE(ctx.carry.pending());
  rig.fsm->plan();
  EXPECT_EQ(planner.calls, 1);
  EXPECT_GT(planner.last_receiver_stop, 0.0);  // a receiver will reach for it there
}

TEST(PlannedTargets, AGiveWhoseReceiverStaysUnseenStillAsksWhereToWait) {
  Rig rig(true);
  rig.plan_stage = false;
  FakePlanner planner;
  rig.fsm->setPlanner(&planner);
  rig.world.dropout = true;
  ASSERT_TRUE(rig.runUntilState("HoldReady", 1.0)) << rig.fsm->activePath();
  ASSERT_TRUE(rig.runUntil([&] { return rig.fsm->context().carry.pending(); }, 1.0));
  rig.fsm->plan();
  EXPECT_EQ(planner.calls, 1);
}

}  // namespace
}  // namespace handover::fsm::test
