// The channel table: one row per channel, each row copies, compares and
// sends exactly its own channel, and a handle undoes every channel of the
// table (the bug this table fixed: undo() stopped before the gains and the
// hand clearance).
#include <gtest/gtest.h>

#include "fsm/handover/controller_handle.hpp"
#include "fsm/handover/scoped_commands.hpp"
#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {

/// A set where every channel differs from its default.
ScopedCommands allChanged() {
  ScopedCommands v;
  v.observation = ObservationTarget::kHand;
  v.tracking = true;
  v.tracking_offset.target_in_observed.translation() = Vector3(0.0, 0.0, -0.08);
  v.tracking_offset.planned = true;
  v.pose.active = true;
  v.pose.pose.translation() = Vector3(0.4, 0.1, 0.3);
  v.posture.active = true;
  v.posture.q.setConstant(0.2);
  v.speed_scale = 0.3;
  v.gains.active = true;
  v.gains.translation = 6.0;
  v.gains.orientation = 12.0;
  v.gains.max_speed = 0.25;
  v.hand_clearance_relaxed = true;
  v.task_switches.mask = 1u << 3;  // a task beyond tracking, pose and posture, switched on
  v.task_switches.on = 1u << 3;
  v.anticipate_rest = true;
  v.pose_gains.active = true;
  v.pose_gains.translation = 60.0;
  v.pose_gains.orientation = 120.0;
  v.fingers_around_object = true;
  return v;
}

/// Changes channel `c` of the ledger through `h` to its value in allChanged(),
/// through the handle's public API (as a state would).
void changeThroughHandle(ControllerHandle& h, Channel c) {
  const ScopedCommands v = allChanged();
  switch (c) {
    case Channel::kObservation: h.setObservationTarget(v.observation); break;
    case Channel::kTracking: h.enableTracking(v.tracking); break;
    case Channel::kTrackingOffset: h.setTrackingOffset(v.tracking_offset); break;
    case Channel::kPose: h.setPoseTarget(v.pose.pose); break;
    case Channel::kPosture: h.setPostureTarget(v.posture.q); break;
    case Channel::kSpeedScale: h.setSpeedScale(v.speed_scale); break;
    case Channel::kGains: h.setTrackingStiffness(v.gains.translation, v.gains.orientation, v.gains.max_speed); break;
    case Channel::kHandClearance: h.relaxHandClearance(v.hand_clearance_relaxed); break;
    case Channel::kTaskSwitches: h.setTaskEnabled(3, true); break;
    case Channel::kAnticipation: h.anticipateRest(v.anticipate_rest); break;
    case Channel::kPoseGains: h.setPoseStiffness(v.pose_gains.translation, v.pose_gains.orientation); break;
    case Channel::kFingersAround: h.fingersAroundObject(v.fingers_around_object); break;
    case Channel::kCount: break;
  }
}

TEST(ScopedCommands, EveryRowTouchesItsOwnChannelOnly) {
  const ScopedCommands defaults, changed = allChanged();
  ASSERT_NE(defaults, changed);
  for (std::size_t i = 0; i < kNumChannels; ++i) {
    const ChannelEntry& e = channelTable()[i];
    SCOPED_TRACE(e.name);
    EXPECT_EQ(static_cast<std::size_t>(e.channel), i);
    EXPECT_FALSE(e.equal(defaults, changed)) << "allChanged() must change every channel";
    ScopedCommands v;
    e.copy(changed, v);
    EXPECT_TRUE(e.equal(v, changed));
    // every other channel kept its default
    for (std::size_t j = 0; j < kNumChannels; ++j) {
      if (j != i) {
        EXPECT_TRUE(channelTable()[j].equal(v, defaults)) << channelTable()[j].name;
      }
    }
  }
}

TEST(ScopedCommands, EqualityComparesEveryChannel) {
  const ScopedCommands defaults, changed = allChanged();
  for (std::size_t i = 0; i < kNumChannels; ++i) {
    ScopedCommands v;
    channelTable()[i].copy(changed, v);
    EXPECT_NE(v, defaults) << channelTable()[i].name;
    EXPECT_EQ(channelDifferences(v, defaults), channelTable()[i].name);
  }
  EXPECT_EQ(ScopedCommands{}, defaults);
  EXPECT_EQ(channelDifferences(defaults, defaults), "");
}

TEST(ScopedCommands, UndoRestoresEveryChannelOfTheTable) {
  for (std::size_t i = 0; i < kNumChannels; ++i) {
    const Channel c = static_cast<Channel>(i);
    SCOPED_TRACE(channelEntry(c).name);
    RecordingController ctl;
    CommandLedger ledger(ctl);
    ControllerHandle h;
    h.bind(&ledger);
    changeThroughHandle(h, c);
    EXPECT_TRUE(h.touched(c));
    EXPECT_NE(ledger.current(), ScopedCommands{});
    h.undo();
    EXPECT_EQ(ledger.current(), ScopedCommands{}) << channelDifferences(ledger.current(), ScopedCommands{});
    EXPECT_FALSE(h.touched(c));
  }
}

TEST(ScopedCommands, UndoSendsTheRestoredValueToTheController) {
  RecordingController ctl;
  CommandLedger ledger(ctl);
  ControllerHandle h;
  h.bind(&ledger);
  h.setTrackingStiffness(6.0, 12.0);
  h.relaxHandClearance(true);
  ASSERT_TRUE(ctl.gains_active);
  ASSERT_TRUE(ctl.hand_relaxed);
  h.undo();
  EXPECT_FALSE(ctl.gains_active);
  EXPECT_FALSE(ctl.hand_relaxed);
}

}  // namespace
}  // namespace handover::fsm::test
