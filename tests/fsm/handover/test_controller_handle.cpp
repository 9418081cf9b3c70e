// "A state removes from the QP what it added": the handle/ledger mechanism,
// directly and through states of the handover machine.
#include <gtest/gtest.h>

#include "fsm/handover/controller_handle.hpp"
#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {

Isometry at(double x) {
  Isometry T = Isometry::Identity();
  T.translation().x() = x;
  return T;
}

TEST(ControllerHandle, UndoRestoresExactlyTheTouchedChannels) {
  RecordingController ctl;
  CommandLedger ledger(ctl);
  ControllerHandle parent, child;
  parent.bind(&ledger);
  child.bind(&ledger);
  parent.setObservationTarget(ObservationTarget::kObject);
  parent.setPoseTarget(at(0.3));
  child.setObservationTarget(ObservationTarget::kHand);
  child.enableTracking(true);
  child.setSpeedScale(0.4);
  child.setGripper(0.0, 40.0);  // persistent
  EXPECT_TRUE(child.touched(Channel::kObservation));
  EXPECT_FALSE(child.touched(Channel::kPose));
  ctl.calls.clear();
  child.undo();
  EXPECT_EQ(ctl.observation, ObservationTarget::kObject);  // the parent's value, not the default
  EXPECT_FALSE(ctl.tracking);
  EXPECT_DOUBLE_EQ(ctl.speed, 1.0);
  EXPECT_TRUE(ctl.pose_active);
  EXPECT_DOUBLE_EQ(ctl.pose.translation().x(), 0.3);
  EXPECT_DOUBLE_EQ(ctl.gripper_width, 0.0);  // not undone
  EXPECT_EQ(ctl.calls.size(), 3u);           // observation, tracking, speed: nothing else
  parent.undo();
  EXPECT_EQ(ctl.observation, ObservationTarget::kNone);
  EXPECT_FALSE(ctl.pose_active);
}

TEST(ControllerHandle, SecondChangeKeepsFirstSavedValue) {
  RecordingController ctl;
  CommandLedger ledger(ctl);
  ControllerHandle h;
  h.bind(&ledger);
  h.setPoseTarget(at(0.1));
  h.setTrackingOffset(at(0.2));
  h.setPoseTarget(at(0.5));  // a second change of the same channel
  h.undo();
  EXPECT_FALSE(ledger.current().pose.active);
  EXPECT_TRUE(ledger.current().tracking_offset.target_in_observed.isApprox(Isometry::Identity()));
}

TEST(ControllerHandle, EveryStateLeavesNothingBehind) {
  // run a full take, then stop: all scoped channels are back to the defaults
  Rig rig;
  rig.world.moveHand(Vector3(0.55, 0.0, 0.30), 0.5);
  ASSERT_TRUE(rig.runUntilState("WaitForRelease", 10.0));
  const ScopedCommands& cur = rig.fsm->context().ledger->current();
  EXPECT_TRUE(cur.tracking);  // WaitForRelease follows the object the person still holds
  EXPECT_EQ(cur.observation, ObservationTarget::kObject);
  EXPECT_TRUE(cur.hand_clearance_relaxed);
  rig.fsm->stop();
  EXPECT_EQ(cur, ScopedCommands()) << channelDifferences(cur, ScopedCommands());
  EXPECT_FALSE(cur.tracking);
  EXPECT_EQ(cur.observation, ObservationTarget::kNone);
  EXPECT_FALSE(cur.pose.active);
  EXPECT_TRUE(cur.tracking_offset.target_in_observed.isApprox(Isometry::Identity()));
  EXPECT_DOUBLE_EQ(cur.speed_scale, 1.0);
  // the controller saw the same
  EXPECT_FALSE(rig.ctl.tracking);
  EXPECT_EQ(rig.ctl.observation, ObservationTarget::kNone);
  EXPECT_FALSE(rig.ctl.pose_active);
  // the gripper still holds what it grasped
  EXPECT_DOUBLE_EQ(rig.ctl.gripper_width, 0.0);
}

TEST(ControllerHandle, PreemptedPathLeavesOnlyTheStopsChanges) {
  Rig rig;
  rig.world.moveHand(Vector3(0.55, 0.0, 0.30), 0.5);
  ASSERT_TRUE(rig.runUntilState("Grasp", 10.0));
  rig.world.hand = Vector3(2.0, 0, 0);  // hand far from the TCP, arm close
  rig.world.human_distance = 0.02;
  rig.step();
  ASSERT_EQ(rig.fsm->activePath(), "SafetyStop");
  const ScopedCommands& cur = rig.fsm->context().ledger->current();
  // only the stop's own changes remain (tracking off, hold pose); the
  // grasp's observation target and offset are gone
  EXPECT_EQ(cur.observation, ObservationTarget::kNone);
  EXPECT_TRUE(cur.tracking_offset.target_in_observed.isApprox(Isometry::Identity()));
  EXPECT_FALSE(cur.tracking);
  EXPECT_TRUE(cur.pose.active);
}

}  // namespace
}  // namespace handover::fsm::test
