// Slip detection (fsm/handover/object_lost.hpp, the object_lost interrupt of
// config/fsm.yaml): an object that slides out of the gripper after the
// exchange ends the run in the Lost rest state with the outcome "failed";
// a held object does not.
#include <gtest/gtest.h>

#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {


/// Takes the object from the person (release after 0.1 s of grip, then the
/// hand leaves) and runs until the robot retracts with it.
void takeUntilRetract(Rig& rig) {
  rig.world.moveHand(kMeet, 0.5);
  auto since = std::make_shared<double>(-1.0);
  rig.person = [since](World& w) {
    if (!w.robot_grip || !w.person_holds) return;
    if (*since < 0) *since = w.time;
    if (w.time - *since >= 0.1) {
      w.person_holds = false;
      w.moveHand(kAway, 0.5);
    }
  };
  ASSERT_TRUE(rig.runUntilState("Retract", 15.0)) << rig.fsm->activePath();
  rig.runFor(0.3);  // the hand is away now
  ASSERT_TRUE(Rig::endsWith(rig.fsm->activePath(), "Retract")) << rig.fsm->activePath();
}

TEST(ObjectLost, FingersClosingOnNothingEndInLost) {
  Rig rig;
  takeUntilRetract(rig);
  // the object slides out: the fingers close on nothing
  rig.world.robot_grip = false;
  rig.world.object_width = 0.0;
  rig.world.graspable = false;
  ASSERT_TRUE(rig.runUntil([&] { return rig.fsm->done(); }, 2.0)) << rig.fsm->activePath();
  EXPECT_EQ(rig.fsm->activePath(), "Lost");
  EXPECT_STREQ(rig.fsm->stats().outcome, "failed");
  EXPECT_EQ(rig.fsm->stats().handovers, 0);
}

TEST(ObjectLost, WeightLeavingTheGripperEndsInLost) {
  Rig rig;
  takeUntilRetract(rig);
  // the weight leaves the gripper while the fingers stay where they were
  rig.world.robot_grip = false;
  rig.world.graspable = false;
  rig.person = [](World& w) { w.width = w.object_width; };  // fingers stuck at the object's width
  ASSERT_TRUE(rig.runUntil([&] { return rig.fsm->done(); }, 2.0)) << rig.fsm->activePath();
  EXPECT_EQ(rig.fsm->activePath(), "Lost");
  EXPECT_STREQ(rig.fsm->stats().outcome, "failed");
}

// a push on the held object from below and aside: the vertical share reads 0,
// but the gripper still carries the object's weight's worth of force
TEST(ObjectLost, APushOnTheHeldObjectIsNotALoss) {
  Rig rig;
  takeUntilRetract(rig);
  rig.world.share = 0.0;
  rig.world.tool_contact.head<3>() = Vector3(-0.7, -0.7, 0.4) * rig.world.mass * 9.81 + Vector3(0, 0, rig.world.mass * 9.81);
  rig.runFor(0.5);
  EXPECT_TRUE(Rig::endsWith(rig.fsm->activePath(), "Retract")) << rig.fsm->activePath();
  // the same share with nothing on the gripper is the weight gone
  rig.world.tool_contact.setZero();
  rig.world.mass = 0.0;  // the fake estimator's load: nothing
  ASSERT_TRUE(rig.runUntil([&] { return rig.fsm->done(); }, 1.0)) << rig.fsm->activePath();
  EXPECT_EQ(rig.fsm->activePath(), "Lost");
}

TEST(ObjectLost, HeldObjectIsNotLost) {
  Rig rig;
  takeUntilRetract(rig);
  ASSERT_TRUE(rig.runUntil([&] { return rig.fsm->done(); }, 15.0)) << rig.fsm->activePath();
  EXPECT_EQ(rig.fsm->activePath(), "Done");
  EXPECT_STREQ(rig.fsm->stats().outcome, "success");
}

}  // namespace
}  // namespace handover::fsm::test
