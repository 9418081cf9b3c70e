// The scoped controller channels, as one table: what a state may change and
// must give back when it ends (ControllerHandle::undo). Each channel is one
// value type with operator==, one member of ScopedCommands and one row of
// channelTable(), which knows how to copy, compare and send that member. The
// ledger, the handle and the tests loop over the table, so adding a channel
// is a value, a member and a row; nothing else enumerates the channels.
//
// Frames and units as in controller_interface.hpp (world frame, SI units).
// Real-time: everything here is RT safe (plain values, no allocation).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "fsm/handover/controller_interface.hpp"

namespace handover::fsm {

/// A set-point that is either active with a value or cleared (the
/// controller's default then applies).
struct PoseCommand {
  bool active = false;
  Isometry pose = Isometry::Identity();  ///< TCP in the world
  Vector6 velocity = Vector6::Zero();    ///< the set-point's motion [m/s; rad/s], world axes (zero: fixed)
};
struct PostureCommand {
  bool active = false;
  Vector7 q = Vector7::Zero();    ///< rad, the 7 arm joints in chain order
  Vector7 qd = Vector7::Zero();   ///< rad/s, the reference's motion (zero: fixed)
  Vector7 qdd = Vector7::Zero();  ///< rad/s^2
};
/// A task's phase gains (inactive: the configured ones): the tracking
/// task's (gains) and the pose task's (pose_gains).
using GainsCommand = TaskGains;
/// Tasks a state switched on or off by handle (handles 0..31), beyond those
/// with a channel of their own (tracking, pose): bit i of `mask` says task i
/// is switched, bit i of `on` to what; a task whose bit is clear is as
/// configured.
struct TaskSwitches {
  std::uint32_t mask = 0;
  std::uint32_t on = 0;
};
bool operator==(const TaskSwitches& a, const TaskSwitches& b);
inline bool operator!=(const TaskSwitches& a, const TaskSwitches& b) { return !(a == b); }

/// Exact comparisons (a restored value is the very value saved).
bool operator==(const PoseCommand& a, const PoseCommand& b);
bool operator==(const TrackingOffset& a, const TrackingOffset& b);
bool operator==(const PostureCommand& a, const PostureCommand& b);
bool operator==(const GainsCommand& a, const GainsCommand& b);
inline bool operator!=(const PoseCommand& a, const PoseCommand& b) { return !(a == b); }
inline bool operator!=(const TrackingOffset& a, const TrackingOffset& b) { return !(a == b); }
inline bool operator!=(const PostureCommand& a, const PostureCommand& b) { return !(a == b); }
inline bool operator!=(const GainsCommand& a, const GainsCommand& b) { return !(a == b); }

/// Values of the scoped channels; default-constructed = the controller's
/// state before any state ran.
struct ScopedCommands {
  ObservationTarget observation = ObservationTarget::kNone;
  bool tracking = false;
  TrackingOffset tracking_offset;  ///< target frame in the observed frame
  PoseCommand pose;
  PostureCommand posture;
  double speed_scale = 1.0;  ///< 0..1
  GainsCommand gains;
  bool hand_clearance_relaxed = false;
  TaskSwitches task_switches;
  bool anticipate_rest = false;  ///< targets where the person's reach will end
  GainsCommand pose_gains;       ///< the pose task's (e.g. a stiff hold while the person lets go)
  bool fingers_around_object = false;  ///< the fingers are around the object the person holds
};

/// Every channel compared through the table.
bool operator==(const ScopedCommands& a, const ScopedCommands& b);
inline bool operator!=(const ScopedCommands& a, const ScopedCommands& b) { return !(a == b); }

/// Channel ids: the index of the channel's row in channelTable().
enum class Channel : std::uint8_t {
  kObservation,
  kTracking,
  kTrackingOffset,
  kPose,
  kPosture,
  kSpeedScale,
  kGains,
  kHandClearance,
  kTaskSwitches,
  kAnticipation,
  kPoseGains,
  kFingersAround,
  kCount
};
constexpr std::size_t kNumChannels = static_cast<std::size_t>(Channel::kCount);

/// The handles of the tasks the named channels address (resolved once by
/// the ledger through ControllerInterface::taskHandle; -1: none).
struct TaskHandles {
  int tracking = -1;
  int pose = -1;
  int posture = -1;
};

/// One row of the table.
struct ChannelEntry {
  Channel channel;
  const char* name;  ///< for messages and tests
  /// Copies this channel's member only (other channels' values survive).
  void (*copy)(const ScopedCommands& from, ScopedCommands& to);
  bool (*equal)(const ScopedCommands& a, const ScopedCommands& b);
  /// Writes this channel's member of `value` to the controller.
  void (*send)(ControllerInterface& controller, const TaskHandles& tasks, const ScopedCommands& value);
};

/// The table, kNumChannels rows in Channel order.
const ChannelEntry* channelTable();
inline const ChannelEntry& channelEntry(Channel c) { return channelTable()[static_cast<std::size_t>(c)]; }

/// Names of the channels whose values differ ("" when equal); for test
/// messages (allocates, not RT safe).
std::string channelDifferences(const ScopedCommands& a, const ScopedCommands& b);

}  // namespace handover::fsm
