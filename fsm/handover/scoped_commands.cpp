#include "fsm/handover/scoped_commands.hpp"

namespace handover::fsm {

namespace {

bool same(const Isometry& a, const Isometry& b) { return a.matrix() == b.matrix(); }
template <class T>
bool same(const T& a, const T& b) {
  return a == b;
}

// copy and compare one member, given as a pointer to member
template <auto Member>
void copyMember(const ScopedCommands& from, ScopedCommands& to) {
  to.*Member = from.*Member;
}
template <auto Member>
bool equalMember(const ScopedCommands& a, const ScopedCommands& b) {
  return same(a.*Member, b.*Member);
}
template <auto Member>
constexpr ChannelEntry row(Channel c, const char* name,
                           void (*send)(ControllerInterface&, const TaskHandles&, const ScopedCommands&)) {
  return ChannelEntry{c, name, &copyMember<Member>, &equalMember<Member>, send};
}

// what each channel's value means to the controller: tasks through their handles
using H = TaskHandles;
void sendObservation(ControllerInterface& ctl, const H&, const ScopedCommands& v) {
  ctl.setObservationTarget(v.observation);
}
void sendTracking(ControllerInterface& ctl, const H& t, const ScopedCommands& v) {
  ctl.setTaskEnabled(t.tracking, v.tracking);
}
void sendTrackingOffset(ControllerInterface& ctl, const H& t, const ScopedCommands& v) {
  ctl.setTaskOffset(t.tracking, v.tracking_offset);
}
void sendPose(ControllerInterface& ctl, const H& t, const ScopedCommands& v) {
  if (v.pose.active) {
    TaskTarget target;
    target.kind = TaskTarget::Kind::kPose;
    target.pose = v.pose.pose;
    target.velocity = v.pose.velocity;
    ctl.setTaskTarget(t.pose, target);
  }
  ctl.setTaskEnabled(t.pose, v.pose.active);
}
void sendPosture(ControllerInterface& ctl, const H& t, const ScopedCommands& v) {
  TaskTarget target;  // inactive: the configured posture
  if (v.posture.active) {
    target.kind = TaskTarget::Kind::kJoints;
    target.q = v.posture.q;
    target.qd = v.posture.qd;
    target.qdd = v.posture.qdd;
  }
  ctl.setTaskTarget(t.posture, target);
}
void sendSpeedScale(ControllerInterface& ctl, const H&, const ScopedCommands& v) { ctl.setSpeedScale(v.speed_scale); }
void sendGains(ControllerInterface& ctl, const H& t, const ScopedCommands& v) { ctl.setTaskGains(t.tracking, v.gains); }
void sendPoseGains(ControllerInterface& ctl, const H& t, const ScopedCommands& v) { ctl.setTaskGains(t.pose, v.pose_gains); }
void sendHandClearance(ControllerInterface& ctl, const H&, const ScopedCommands& v) {
  ctl.relaxHandClearance(v.hand_clearance_relaxed);
}
void sendFingersAround(ControllerInterface& ctl, const H&, const ScopedCommands& v) {
  ctl.fingersAroundObject(v.fingers_around_object);
}
void sendAnticipation(ControllerInterface& ctl, const H&, const ScopedCommands& v) {
  ctl.anticipateRest(v.anticipate_rest);
}
void sendTaskSwitches(ControllerInterface& ctl, const H& t, const ScopedCommands& v) {
  for (int i = 0; i < 32; ++i) {
    if (i == t.tracking || i == t.pose) continue;  // switched by their own channels
    const std::uint32_t bit = 1u << i;
    if (v.task_switches.mask & bit) ctl.setTaskEnabled(i, (v.task_switches.on & bit) != 0);
    else ctl.resetTaskEnabled(i);
  }
}

using S = ScopedCommands;
constexpr ChannelEntry kTable[] = {
    row<&S::observation>(Channel::kObservation, "observation", &sendObservation),
    row<&S::tracking>(Channel::kTracking, "tracking", &sendTracking),
    row<&S::tracking_offset>(Channel::kTrackingOffset, "tracking_offset", &sendTrackingOffset),
    row<&S::pose>(Channel::kPose, "pose", &sendPose),
    row<&S::posture>(Channel::kPosture, "posture", &sendPosture),
    row<&S::speed_scale>(Channel::kSpeedScale, "speed_scale", &sendSpeedScale),
    row<&S::gains>(Channel::kGains, "gains", &sendGains),
    row<&S::hand_clearance_relaxed>(Channel::kHandClearance, "hand_clearance", &sendHandClearance),
    row<&S::task_switches>(Channel::kTaskSwitches, "task_switches", &sendTaskSwitches),
    row<&S::anticipate_rest>(Channel::kAnticipation, "anticipate_rest", &sendAnticipation),
    row<&S::pose_gains>(Channel::kPoseGains, "pose_gains", &sendPoseGains),
    row<&S::fingers_around_object>(Channel::kFingersAround, "fingers_around_object", &sendFingersAround),
};
static_assert(sizeof(kTable) / sizeof(kTable[0]) == kNumChannels, "one row per channel");

constexpr bool rowsInChannelOrder() {
  for (std::size_t i = 0; i < kNumChannels; ++i)
    if (static_cast<std::size_t>(kTable[i].channel) != i) return false;
  return true;
}
static_assert(rowsInChannelOrder(), "row i is channel i");

}  // namespace

bool operator==(const PoseCommand& a, const PoseCommand& b) { return a.active == b.active && same(a.pose, b.pose) && a.velocity == b.velocity; }
bool operator==(const TrackingOffset& a, const TrackingOffset& b) {
  return a.planned == b.planned && same(a.target_in_observed, b.target_in_observed) &&
         (!a.planned || a.joint_plan == b.joint_plan) && a.approach_speed == b.approach_speed &&
         a.approach_acceleration == b.approach_acceleration;
}
bool operator==(const PostureCommand& a, const PostureCommand& b) { return a.active == b.active && a.q == b.q && a.qd == b.qd && a.qdd == b.qdd; }
bool operator==(const GainsCommand& a, const GainsCommand& b) {
  return a.active == b.active && a.translation == b.translation && a.orientation == b.orientation &&
         a.max_speed == b.max_speed;
}

bool operator==(const TaskSwitches& a, const TaskSwitches& b) {
  return a.mask == b.mask && (a.on & a.mask) == (b.on & b.mask);
}

const ChannelEntry* channelTable() { return kTable; }

bool operator==(const ScopedCommands& a, const ScopedCommands& b) {
  for (const ChannelEntry& e : kTable)
    if (!e.equal(a, b)) return false;
  return true;
}

std::string channelDifferences(const ScopedCommands& a, const ScopedCommands& b) {
  std::string out;
  for (const ChannelEntry& e : kTable) {
    if (e.equal(a, b)) continue;
    if (!out.empty()) out += ", ";
    out += e.name;
  }
  return out;
}

}  // namespace handover::fsm
