// The safety layer of the handover machine: slow down and stop.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {


TEST(HandoverSafety, CloseArmSlowsDownWithoutChangingState) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("/Approach", 5.0));
  rig.world.arm_distance = 0.15;  // forearm near the robot, hand still far from the TCP
  rig.step();
  EXPECT_DOUBLE_EQ(rig.ctl.speed, 0.3);
  EXPECT_EQ(rig.ctl.count("speed 0.30"), 1);
  EXPECT_TRUE(Rig::endsWith(rig.fsm->activePath(), "Approach"));
  rig.world.arm_distance = 1.0;
  rig.step();
  EXPECT_DOUBLE_EQ(rig.ctl.speed, 1.0);  // the overlay's teardown restored the scale
  EXPECT_EQ(rig.ctl.count("speed 1.00"), 1);
  EXPECT_EQ(rig.fsm->stats().safety_stops, 0);
}

TEST(HandoverSafety, TooCloseStopsTearsDownAndResumes) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("/Approach", 5.0));
  ASSERT_TRUE(rig.ctl.tracking);
  const double gripper = rig.ctl.gripper_width;
  rig.world.arm_distance = 0.02;  // the forearm pushes in
  rig.step();
  EXPECT_EQ(rig.fsm->activePath(), "SafetyStop");
  // the approach's tracking and observation were removed, the TCP is held
  EXPECT_FALSE(rig.ctl.tracking);
  EXPECT_EQ(rig.ctl.observation, ObservationTarget::kNone);
  EXPECT_TRUE(rig.ctl.pose_active);
  EXPECT_EQ(rig.ctl.gripper_width, gripper);  // gripper untouched
  EXPECT_EQ(rig.fsm->stats().safety_stops, 1);
  rig.runFor(1.0);
  EXPECT_EQ(rig.fsm->activePath(), "SafetyStop");  // stays while the person is close
  EXPECT_LT(rig.world.tcp_vel.norm(), 0.05);
  rig.world.arm_distance = 1.0;
  ASSERT_TRUE(rig.runUntilState("/Approach", 2.0));  // clear for 0.5 s, then the handover resumes
  const auto leaves = rig.leaves();
  // closer than the slow-down distance too, so the overlay started first
  const Leaves expected{"SelectDirection", "WaitForOffer", "Approach", "SlowDown", "SafetyStop",
                        "SelectDirection", "WaitForOffer", "Approach"};
  EXPECT_EQ(leaves, expected);
  bool marked = false;
  for (const auto& e : rig.fsm->machine().history().entries()) marked = marked || (e.interrupt && e.path() == "SafetyStop");
  EXPECT_TRUE(marked);
}

// a person who stays too close is given room: after yield_after (1 s) of stop
// the TCP backs off toward the safe pose's position, keeping its orientation
TEST(HandoverSafety, APersonWhoStaysTooCloseIsGivenRoom) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("/Approach", 5.0));
  const Vector3 safe = rig.fsm->params().safe_pose.translation();
  ASSERT_TRUE(rig.runUntil([&] { return (rig.world.tcp.translation() - safe).norm() > 0.15; }, 5.0));
  rig.world.arm_distance = 0.02;
  rig.step();
  ASSERT_EQ(rig.fsm->activePath(), "SafetyStop");
  const Isometry stopped = rig.ctl.pose;
  rig.runFor(0.8);
  EXPECT_LT((rig.ctl.pose.translation() - stopped.translation()).norm(), 1e-9);  // held at first
  EXPECT_LT(rig.world.tcp_vel.norm(), 0.05);
  const double before = (rig.world.tcp.translation() - safe).norm();
  rig.runFor(0.5);
  EXPECT_EQ(rig.fsm->activePath(), "SafetyStop");
  EXPECT_LT((rig.ctl.pose.translation() - safe).norm(), 1e-9);
  EXPECT_TRUE(rig.ctl.pose.linear().isApprox(stopped.linear()));
  EXPECT_LT((rig.world.tcp.translation() - safe).norm(), before - 0.05);  // on its way back
  rig.world.arm_distance = 1.0;
  EXPECT_TRUE(rig.runUntilState("/Approach", 2.0));  // clear: the handover resumes
}

TEST(HandoverSafety, HandInGraspZoneIsNotAnIntrusion) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("Grasp", 10.0));
  rig.world.human_distance = 0.02;  // the hand is at the gripper: that is the handover
  rig.runFor(0.2);
  EXPECT_NE(rig.fsm->activePath(), "SafetyStop");
  EXPECT_EQ(rig.fsm->stats().safety_stops, 0);
  EXPECT_DOUBLE_EQ(rig.ctl.speed, 1.0);
}

TEST(HandoverSafety, HandAtTheTrackingTargetIsNotAnIntrusionButTheForearmIs) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("/Approach", 5.0));
  // the hand is where the gripper is going (the grasp frame), the TCP still
  // farther than the grasp-zone radius: closeness of the hand is the handover
  rig.world.human_distance = 0.02;
  rig.runFor(0.2);
  EXPECT_TRUE(Rig::endsWith(rig.fsm->activePath(), "Approach"));
  EXPECT_EQ(rig.fsm->stats().safety_stops, 0);
  // the same closeness of the forearm stops the robot
  rig.world.arm_distance = 0.02;
  rig.step();
  EXPECT_EQ(rig.fsm->activePath(), "SafetyStop");
}

/// Stops the robot for 0.2 s (the person's forearm 2 cm away) and clears.
void stopAndClear(Rig& rig) {
  rig.world.arm_distance = 0.02;
  rig.step();
  ASSERT_EQ(rig.fsm->activePath(), "SafetyStop");
  rig.runFor(0.2);
  rig.world.arm_distance = 1.0;
}

/// A stop and its clearing, then: the machine ends stowed (the last leaves
/// SafetyStop, SelectDirection, Stow, Done), one handover, never in
/// `other_direction` (the other direction's first state).
void stopAndResumeWithTheStow(Rig& rig, const std::string& other_direction) {
  stopAndClear(rig);
  ASSERT_TRUE(rig.runUntil([&] { return rig.fsm->done(); }, 15.0)) << rig.fsm->activePath();
  const Leaves leaves = rig.leaves();
  EXPECT_EQ(Leaves(leaves.end() - 4, leaves.end()), (Leaves{"SafetyStop", "SelectDirection", "Stow", "Done"}));
  EXPECT_EQ(std::find(leaves.begin(), leaves.end(), other_direction), leaves.end());
  EXPECT_STREQ(rig.fsm->stats().outcome, "success");
  EXPECT_EQ(rig.fsm->stats().handovers, 1);
}

// A stop after the object changed hands resumes with the stow: restarted from
// the choice of direction, the robot read the taken object in its gripper as
// one to give and offered it back to the person (and after a give, waited to
// take an object from them).
TEST(HandoverSafety, AStopAfterATakesReleaseResumesWithTheStowNotAGive) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  auto gripped_since = std::make_shared<double>(-1.0);
  rig.person = [gripped_since](World& w) {  // lets go once gripped for 0.1 s, and withdraws
    if (!w.robot_grip) return;
    if (*gripped_since < 0) *gripped_since = w.time;
    if (w.time - *gripped_since >= 0.1 && w.person_holds) {
      w.person_holds = false;
      w.moveHand(w.hand + Vector3(0.3, 0.0, 0.0), 0.5);
    }
  };
  ASSERT_TRUE(rig.runUntilState("/Retract", 20.0)) << rig.fsm->activePath();
  stopAndResumeWithTheStow(rig, "HoldReady");
  EXPECT_TRUE(rig.world.robot_grip);
}

TEST(HandoverSafety, AStopAfterAGivesObjectIsGoneResumesWithTheStowNotATake) {
  Rig rig(true);
  ASSERT_TRUE(rig.runUntilState("WaitForReceiver", 5.0)) << rig.fsm->activePath();
  rig.world.moveHand(Vector3(0.60, 0.0, 0.35), 0.5);
  auto resting_since = std::make_shared<double>(-1.0);
  rig.person = [resting_since](World& w) {  // takes the object resting in the hand, pulls, leaves with it
    if (w.person_holds) {
      w.pull = Vector3(5.0, 0.0, 0.0);
      if (!w.robot_grip) w.moveHand(kAway, 0.3);
      return;
    }
    const bool in_hand = (w.object - (w.hand + w.object_in_hand)).norm() < 0.01 && w.tcp_vel.norm() < 0.01;
    if (!in_hand) return void(*resting_since = -1.0);
    if (*resting_since < 0) *resting_since = w.time;
    if (w.time - *resting_since >= 0.5) w.person_holds = true;
  };
  ASSERT_TRUE(rig.runUntilState("BackOut", 20.0)) << rig.fsm->activePath();
  stopAndResumeWithTheStow(rig, "WaitForOffer");
}

TEST(HandoverSafety, NoInterruptOnceDone) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  rig.world.dropout = true;  // nobody is seen: wait times out
  ASSERT_TRUE(rig.runUntil([&] { return rig.fsm->done(); }, 25.0));
  rig.world.human_distance = 0.02;
  rig.runFor(0.1);
  EXPECT_EQ(rig.fsm->activePath(), "Aborted");
  EXPECT_EQ(rig.fsm->stats().safety_stops, 0);
}

TEST(HandoverSafety, NonFiniteInputsAreCountedNotFollowed) {
  Rig rig;
  rig.world.moveHand(kMeet, 0.5);
  ASSERT_TRUE(rig.runUntilState("/Approach", 5.0));
  HandoverInput in = rig.world.input(rig.ctl);
  in.object.pose.translation().x() = std::nan("");
  in.wrench[2] = std::nan("");
  in.human_distance = std::nan("");
  const Vector3 force_before = rig.fsm->context().force;
  rig.fsm->step(in);
  EXPECT_EQ(rig.fsm->stats().bad_input_cycles, 1);
  EXPECT_TRUE(rig.fsm->context().force.allFinite());
  EXPECT_TRUE(rig.fsm->context().force.isApprox(force_before));
  EXPECT_FALSE(rig.fsm->context().in.object.valid);
  // an unknown distance is treated as the worst case: stop
  EXPECT_EQ(rig.fsm->activePath(), "SafetyStop");
}

}  // namespace
}  // namespace handover::fsm::test
