// HandoverCycle keeps the stage order and the input ages its header states:
// the arm's sensing and the person's estimate are this cycle's; the TCP pose,
// the tracking target and the robot-person distances the state machine sees
// are those of the previous Controller::step; the command is this cycle's QP
// torque with the state machine's gripper command. The carry's placement
// search runs in plan(), never in step().
#include <gtest/gtest.h>

#include <cmath>

#include "control/so3.hpp"
#include "runtime/collision_queries.hpp"
#include "runtime/handover_cycle.hpp"

namespace handover::runtime {
namespace {

/// A person sampled every cycle: the grip point at `hand` (plus `wobble`
/// sin(t) m along y), the forearm from `forearm` with its z along world x,
/// the upper arm's origin `upper` beyond it (world offset); all of it moving
/// at `sweep` (m/s).
class PersonInView : public perception::PoseSource {
 public:
  PersonInView(const Eigen::Vector3d& hand, double wobble, const Eigen::Vector3d& forearm,
               const Eigen::Vector3d& upper, const Eigen::Vector3d& sweep)
      : hand_(hand), forearm_(forearm), upper_(upper), sweep_(sweep), wobble_(wobble) {}
  bool poll(double now, perception::PoseSample& out) override {
    if (now <= last_) return false;
    last_ = now;
    out.stamp = now;
    const Eigen::Vector3d shift = sweep_ * now;
    Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
    hand.translation() = hand_ + shift + Eigen::Vector3d(0.0, wobble_ * std::sin(now), 0.0);
    out.hand = perception::Pose::fromIsometry(hand);
    Eigen::Isometry3d forearm = Eigen::Isometry3d::Identity();
    forearm.translation() = forearm_ + shift;
    forearm.linear() = control::expRotation(control::Vector3(0.0, M_PI / 2, 0.0));  // z along world x
    out.forearm = perception::Pose::fromIsometry(forearm);
    Eigen::Isometry3d upper = forearm;
    upper.translation() += upper_;
    out.upper_arm = perception::Pose::fromIsometry(upper);
    return true;
  }

 private:
  Eigen::Vector3d hand_, forearm_, upper_, sweep_;
  double wobble_;
  double last_ = -1.0;
};

/// The person's hand 0.4 m in front of the TCP, the forearm straight
/// through the robot's base (so the robot-arm distance is short).
PersonInView handInView() {
  return PersonInView(Eigen::Vector3d(0.7, 0.0, 0.3), 0.05, Eigen::Vector3d(-0.1, 0.0, 0.3),
                      Eigen::Vector3d(0.0, 0.0, 0.3), Eigen::Vector3d::Zero());
}

/// An arm that moves on its own (a slow sine on every joint), so that
/// values of one cycle and of the previous one differ.
io::ArmState armAt(const io::Vector7& q0, double t) {
  io::ArmState a;
  a.time = t;
  for (int j = 0; j < 7; ++j) {
    a.q[j] = q0[j] + 0.05 * std::sin(2.0 * t + j);
    a.qd[j] = 0.1 * std::cos(2.0 * t + j);
  }
  a.finger_width = 0.08;
  return a;
}

TEST(HandoverCycle, StateMachineSeesThisCyclesSensingAndLastCyclesController) {
  HandoverCycle cycle(defaultCycleSettings());
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  PersonInView person = handInView();
  cycle.start(armAt(q0, 0.0), false);
  for (int k = 0; k < 50; ++k) {
    const double t = k * 0.001;
    const io::ArmState arm = armAt(q0, t);
    // what the previous Controller::step left
    const Eigen::Isometry3d tcp_before = cycle.controller().tcpPose();
    const Eigen::Isometry3d target_before = cycle.controller().graspFrame().pose;
    const auto& cm = cycle.collision().collisionModel();
    const double arm_d_before = std::min(
        2.0, personDistance(cm, cycle.collision().collisionData(), cycle.handGripperRule(), false, PersonPart::kArm));

    const io::ArmCommand& cmd = cycle.step(t, arm, person);
    const fsm::HandoverInput& in = cycle.fsmInput();
    // this cycle
    EXPECT_EQ(in.time, t);
    EXPECT_TRUE(in.q == arm.q);
    EXPECT_TRUE(in.qd == arm.qd);
    EXPECT_TRUE(in.hand.pose.matrix() == cycle.estimate().human.hand.matrix());
    // one cycle old
    EXPECT_TRUE(in.tcp_pose.matrix() == tcp_before.matrix()) << "k = " << k;
    EXPECT_TRUE(in.target_pose.matrix() == target_before.matrix()) << "k = " << k;
    EXPECT_DOUBLE_EQ(in.arm_distance, arm_d_before);
    // the command is this cycle's QP
    EXPECT_TRUE(cmd.tau == cycle.controller().lastTau());
    EXPECT_DOUBLE_EQ(cmd.gripper_width, cycle.adapter().gripperWidth());
    if (k > 0) {
      // the arm moved, so last cycle's TCP is not this cycle's
      EXPECT_FALSE(cycle.controller().tcpPose().matrix().isApprox(in.tcp_pose.matrix(), 1e-12));
    }
  }
  EXPECT_TRUE(cycle.fsmInput().hand.valid);
  EXPECT_LT(cycle.fsmInput().arm_distance, 0.1);  // the person's forearm is in the collision model
}

TEST(HandoverCycle, SharingTheObjectSwitchesTheScopedRules) {
  // config/collision.yaml: the gripper keeps the sensor margin from the
  // person's upper arm and the hand's clearance from the forearm while apart,
  // and only the safety distance from either while it shares the object with
  // the person's hand
  HandoverCycle cycle(defaultCycleSettings());
  const auto& cm = cycle.collision().collisionModel();
  const int apart = cm.ruleIndex("person_arm_gripper");
  const int sharing = cm.ruleIndex("person_arm_gripper_sharing");
  const int forearm = cm.ruleIndex("person_forearm_gripper");
  ASSERT_GE(apart, 0);
  ASSERT_GE(sharing, 0);
  ASSERT_GE(forearm, 0);
  EXPECT_TRUE(cycle.collision().ruleEnabled(apart));
  EXPECT_FALSE(cycle.collision().ruleEnabled(sharing));
  EXPECT_TRUE(cycle.collision().ruleEnabled(forearm));
  ControllerAdapter& adapter = cycle.adapter();
  adapter.relaxHandClearance(true);
  EXPECT_FALSE(cycle.collision().ruleEnabled(apart));
  EXPECT_TRUE(cycle.collision().ruleEnabled(sharing));
  EXPECT_FALSE(cycle.collision().ruleEnabled(forearm));
  EXPECT_FALSE(cycle.collision().ruleEnabled(cycle.handGripperRule()));
  adapter.relaxHandClearance(false);
  EXPECT_TRUE(cycle.collision().ruleEnabled(apart));
  EXPECT_FALSE(cycle.collision().ruleEnabled(sharing));
  EXPECT_TRUE(cycle.collision().ruleEnabled(forearm));
  EXPECT_TRUE(cycle.collision().ruleEnabled(cycle.handGripperRule()));
}

// The gripper keeps off the hand whose object its fingers close on (a take:
// the person still carries it), not off a receiver's hand closing on the
// object the robot carries (a give: the payload is set)
TEST(HandoverCycle, TheTakingRuleIsOnOnlyWhileSharingAnObjectThePersonCarries) {
  HandoverCycle cycle(defaultCycleSettings());
  const auto& cm = cycle.collision().collisionModel();
  const int taking = cm.ruleIndex("person_hand_gripper_taking");
  ASSERT_GE(taking, 0);
  ASSERT_EQ(cm.rule_scope[static_cast<std::size_t>(taking)], control::RuleScope::kTaking);
  ControllerAdapter& adapter = cycle.adapter();
  EXPECT_FALSE(cycle.collision().ruleEnabled(taking));  // apart
  adapter.relaxHandClearance(true);
  EXPECT_TRUE(cycle.collision().ruleEnabled(taking));   // the fingers close on the person's object
  adapter.setPayload(0.5, fsm::Vector3::Zero());
  EXPECT_FALSE(cycle.collision().ruleEnabled(taking));  // the robot carries it
  adapter.clearPayload();
  EXPECT_TRUE(cycle.collision().ruleEnabled(taking));
  // the fingers hold it, the person too (WaitForRelease): nothing left for the rule to keep
  adapter.fingersAroundObject(true);
  EXPECT_FALSE(cycle.collision().ruleEnabled(taking));
  EXPECT_FALSE(cycle.collision().ruleEnabled(cycle.handGripperRule()));  // still sharing: apart rules off
  adapter.fingersAroundObject(false);
  EXPECT_TRUE(cycle.collision().ruleEnabled(taking));
  adapter.relaxHandClearance(false);
  EXPECT_FALSE(cycle.collision().ruleEnabled(taking));
  // no sensing budget on it: the hand and the object are where the fingers work
  for (const control::CollisionPair& p : cm.pairs) {
    if (p.rule == taking) {
      EXPECT_EQ(p.margin, 0.0);
    }
  }
}

// The gripper keeps off the object the person holds out (it lines up beside it) but not
// while its fingers are around it (WaitForRelease). The clearances from the person are
// not the fingers' business here.
TEST(HandoverCycle, TheObjectRuleIsOffWhileTheFingersAreAroundTheObject) {
  HandoverCycle cycle(defaultCycleSettings());
  const auto& cm = cycle.collision().collisionModel();
  const int object = cm.ruleIndex("object_gripper");
  ASSERT_GE(object, 0);
  ControllerAdapter& adapter = cycle.adapter();
  EXPECT_TRUE(cycle.collision().ruleEnabled(object));  // apart, nothing held
  adapter.fingersAroundObject(true);
  EXPECT_FALSE(cycle.collision().ruleEnabled(object));
  EXPECT_TRUE(cycle.collision().ruleEnabled(cycle.handGripperRule()));  // the person's hand: as apart
  adapter.fingersAroundObject(false);
  EXPECT_TRUE(cycle.collision().ruleEnabled(object));
}

// Trackers do not see the trunk: with a declared stand the cycle places it
// under the tracked shoulder (the upper arm's origin), shifted to the body's
// midline, facing the declared way, on the floor; without one it stays out.
// The collision dampers read how fast each part of the person comes at the
// arm: the forearm and the upper arm too, not only the hand. Taken as still,
// a forearm coming at 0.3 m/s into the open gripper beside the object read a
// pair distance that grew (+0.2 m/s) while it fell 4 cm, and touched the
// gripper (g491_00039).
TEST(HandoverCycle, TheCollisionModelMovesThePersonsForearmAndUpperArmAsTheyMove) {
  HandoverCycle cycle(defaultCycleSettings());
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  // the whole arm sweeping sideways at 0.3 m/s (+y)
  PersonInView person(Eigen::Vector3d(0.7, 0.0, 0.3), 0.0, Eigen::Vector3d(0.7, 0.0, 0.3),
                      Eigen::Vector3d(0.27, 0.0, 0.0), Eigen::Vector3d(0.0, 0.3, 0.0));
  cycle.start(armAt(q0, 0.0), false);
  for (int k = 0; k <= 500; ++k) cycle.step(k * 0.001, armAt(q0, k * 0.001), person);
  const auto& cm = cycle.collision().collisionModel();
  const auto& cd = cycle.collision().collisionData();
  for (const int body : {cm.human_forearm, cm.human_upper_arm, cm.human_hand}) {
    const Eigen::Vector3d v = cd.body_twist[body].head<3>();
    EXPECT_NEAR(v.y(), 0.3, 0.01) << cm.bodies[body].name;
    EXPECT_NEAR(v.x(), 0.0, 0.01) << cm.bodies[body].name;
    EXPECT_NEAR(v.z(), 0.0, 0.01) << cm.bodies[body].name;
  }
}

TEST(HandoverCycle, TrunkStandsUnderTheTrackedShoulder) {
  CycleSettings s = defaultCycleSettings();
  s.stand.declared = true;
  s.stand.yaw = M_PI;            // facing the robot from +x: the person's right is +y
  s.stand.shoulder_side = 0.2;   // a right hand: the shoulder 0.2 m right of the midline
  HandoverCycle cycle(s);
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  PersonInView person = handInView();
  cycle.start(armAt(q0, 0.0), false);
  cycle.step(0.0, armAt(q0, 0.0), person);
  cycle.step(0.001, armAt(q0, 0.001), person);
  const auto& cm = cycle.collision().collisionModel();
  const auto& cd = cycle.collision().collisionData();
  const Eigen::Vector3d shoulder = cycle.estimate().human.upper_arm.translation();
  const Eigen::Isometry3d torso = cd.body_pose[cm.human_torso] * cm.bodies[cm.human_torso].local.inverse();
  EXPECT_NEAR(torso.translation().x(), shoulder.x(), 1e-9);
  EXPECT_NEAR(torso.translation().y(), shoulder.y() - 0.2, 1e-9);
  EXPECT_NEAR(torso.translation().z(), -0.75, 1e-9);
  EXPECT_TRUE(torso.linear().isApprox(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-9));
  // the head above it, at the stature's head height
  const Eigen::Vector3d head = cd.body_pose[cm.human_head].translation();
  EXPECT_NEAR(head.z(), -0.75 + s.collision.person.trunk.head_centre, 1e-9);

  // no declared stand: no trunk pair is ever active
  HandoverCycle blind(defaultCycleSettings());
  PersonInView again = handInView();
  blind.start(armAt(q0, 0.0), false);
  for (int k = 0; k < 5; ++k) blind.step(k * 0.001, armAt(q0, k * 0.001), again);
  const auto& bcm = blind.collision().collisionModel();
  for (int k = 0; k < bcm.numPairs(); ++k) {
    if (bcm.bodies[bcm.pairs[k].other_body].kind == control::CollisionBodyKind::kHumanTrunk) {
      EXPECT_FALSE(blind.collision().collisionData().results[k].active) << bcm.pairLabel(k);
    }
  }
}

/// `inner` until `silent_from` (s), then nothing: a tracker that went silent.
class FallsSilent : public perception::PoseSource {
 public:
  FallsSilent(perception::PoseSource& inner, double silent_from) : inner_(inner), silent_from_(silent_from) {}
  bool poll(double now, perception::PoseSample& out) override { return now < silent_from_ && inner_.poll(now, out); }

 private:
  perception::PoseSource& inner_;
  double silent_from_;
};

/// True if any pair with the person's arm or hand is active (in the QP's reach).
bool personInScene(const HandoverCycle& cycle) {
  const auto& cm = cycle.collision().collisionModel();
  for (int k = 0; k < cm.numPairs(); ++k) {
    const control::CollisionBody& o = cm.bodies[cm.pairs[k].other_body];
    if (o.isPerson() && cycle.collision().collisionData().results[k].active) return true;
  }
  return false;
}

/// The first time (s) from `silent_from` on that the person is out of the collision scene, -1 if not before `until`.
double droppedAt(double unseen_hold, double silent_from, double until) {
  CycleSettings s = defaultCycleSettings();
  s.collision.person.unseen_hold = unseen_hold;
  HandoverCycle cycle(s);
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  PersonInView person = handInView();
  FallsSilent source(person, silent_from);
  cycle.start(armAt(q0, 0.0), false);
  for (int k = 0; k * 0.001 <= until; ++k) {
    const double t = k * 0.001;
    cycle.step(t, armAt(q0, t), source);
    if (t < silent_from) {
      EXPECT_TRUE(personInScene(cycle)) << "seen at t " << t;
    }
    if (t >= silent_from && !personInScene(cycle)) return t;
  }
  return -1.0;
}

// A tracker gone silent does not free the place the person was: they stay in
// the collision scene for collision.person.unseen_hold after the last sample
// (a receiver reaching during a 0.5 s dropout met the presenting arm that had
// dropped them and moved on, g703_00117), then leave it; 0 drops them as soon
// as the estimate turns stale (perception max_gap).
TEST(HandoverCycle, ASilentTrackerLeavesThePersonInTheSceneForTheUnseenHold) {
  const double silent_from = 0.2;
  const double max_gap = defaultCycleSettings().estimator.max_gap;
  const double held = droppedAt(0.5, silent_from, 1.5);
  ASSERT_GT(held, 0.0);
  EXPECT_NEAR(held, silent_from + 0.5, 0.01);
  const double at_once = droppedAt(0.0, silent_from, 1.5);
  ASSERT_GT(at_once, 0.0);
  EXPECT_NEAR(at_once, silent_from + max_gap, 0.01);
}

TEST(HandoverCycle, StartSetsTheGripperAndPayload) {
  HandoverCycle empty(defaultCycleSettings());
  const io::Vector7 q0 = empty.controller().config().posture.target;
  PersonInView person = handInView();
  empty.start(armAt(q0, 0.0), false);
  EXPECT_DOUBLE_EQ(empty.step(0.0, armAt(q0, 0.0), person).gripper_width, 0.08);
  EXPECT_FALSE(empty.adapter().payloadSet());

  HandoverCycle holding(defaultCycleSettings());
  holding.start(armAt(q0, 0.0), true);
  EXPECT_TRUE(holding.adapter().payloadSet());
  EXPECT_DOUBLE_EQ(holding.step(0.0, armAt(q0, 0.0), person).gripper_width, 0.0);
  EXPECT_TRUE(holding.fsmInput().holds_object);
}

/// Nobody in view: no person, no samples.
class NobodyInView : public perception::PoseSource {
 public:
  bool poll(double, perception::PoseSample&) override { return false; }
};

TEST(HandoverCycle, PlanAnswersTheCarryRequestTheStepPosted) {
  CycleSettings s = defaultCycleSettings();
  // a bottle held from above, 8 cm above its centre (the gripper points down)
  control::grasp::GraspSpec top;
  top.placement = Eigen::Translation3d(0.0, 0.0, 0.08) * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX());
  top.preference = s.grasp_selection.declared_preference;
  s.object_grasps.push_back(top);
  s.object.grasp_in_object = top.placement;
  s.object.com_in_tcp = top.placement.inverse() * Eigen::Vector3d::Zero();
  HandoverCycle cycle(s);
  ASSERT_NE(cycle.planning(), nullptr);
  const fsm::HandoverContext& ctx = cycle.machine().context();
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  io::ArmState arm = armAt(q0, 0.0);
  arm.qd.setZero();
  NobodyInView nobody;
  cycle.start(arm, true);  // a give: HoldReady carries the object to the ready pose
  auto inHoldReady = [&] {
    const std::string& p = cycle.machine().activePath();
    return p.size() >= 9 && p.compare(p.size() - 9, 9, "HoldReady") == 0;
  };
  int k = 0;
  for (; k < 10 && !inHoldReady(); ++k) {
    cycle.plan();
    arm.time = k * 0.001;
    cycle.step(arm.time, arm, nobody);
  }
  ASSERT_TRUE(inHoldReady()) << cycle.machine().activePath();
  // nobody in view: HoldReady heads for the ready pose and asks once it has
  // waited its wait_for_person (config/fsm.yaml) for the receiver (no planning stage meanwhile)
  EXPECT_FALSE(ctx.carry.pending());
  for (; k < 500 && !ctx.carry.pending(); ++k) {
    arm.time = k * 0.001;
    cycle.step(arm.time, arm, nobody);
  }
  // HoldReady asked in the step; the step did not search
  ASSERT_TRUE(ctx.carry.pending());
  const int id = ctx.carry.request().id;
  EXPECT_EQ(ctx.carry.answerTo(id), nullptr);
  const fsm::Isometry object_in_tcp = ctx.objectInTcp();
  EXPECT_TRUE(ctx.carry.request().object_in_tcp.isApprox(object_in_tcp));
  const Eigen::Vector3d near = (cycle.machine().params().ready_pose * object_in_tcp).translation();
  EXPECT_TRUE(ctx.carry.request().object_position.isApprox(near));
  EXPECT_TRUE(ctx.carry.request().q == arm.q);
  // meanwhile the ready pose, through the pose task
  EXPECT_TRUE(ctx.ledger->current().pose.active);
  EXPECT_TRUE(ctx.ledger->current().pose.pose.isApprox(cycle.machine().params().ready_pose));

  cycle.plan();
  EXPECT_FALSE(ctx.carry.pending());
  const fsm::ArmPlacement* answer = ctx.carry.answerTo(id);
  ASSERT_NE(answer, nullptr);
  ASSERT_TRUE(answer->found) << "a bottle held from above stands upright near the ready pose";
  // the object upright (its z along world z) near where the ready pose puts it
  const fsm::Isometry object = answer->tcp * object_in_tcp;
  EXPECT_GT(object.linear().col(2).z(), std::cos(10.0 * M_PI / 180.0));
  EXPECT_LT((object.translation() - near).norm(), 0.15);
  EXPECT_TRUE(ctx.ledger->current().pose.active);  // taken when the state runs, in the step

  arm.time = k * 0.001;
  cycle.step(arm.time, arm, nobody);
  EXPECT_TRUE(inHoldReady());
  EXPECT_FALSE(ctx.ledger->current().pose.active);  // the move in joint space
  EXPECT_TRUE(ctx.ledger->current().posture.active);
  // to the placement's configuration (timed with params.carry.joint_speed > 0: from where the arm is)
  const fsm::Vector7 goal = answer->q;
  bool arrived = ctx.ledger->current().posture.q.isApprox(goal, 1e-12);
  for (int n = 0; n < 5000 && !arrived; ++n) {
    arm.time = ++k * 0.001;
    cycle.step(arm.time, arm, nobody);
    arrived = ctx.ledger->current().posture.q.isApprox(goal, 1e-12);
  }
  EXPECT_TRUE(arrived) << ctx.ledger->current().posture.q.transpose();
}

}  // namespace
}  // namespace handover::runtime
