#include "fsm/handover/controller_handle.hpp"

namespace handover::fsm {

const char* toString(ObservationTarget target) {
  switch (target) {
    case ObservationTarget::kNone: return "none";
    case ObservationTarget::kObject: return "object";
    case ObservationTarget::kHand: return "hand";
  }
  return "?";
}

CommandLedger::CommandLedger(ControllerInterface& controller) : controller_(controller) {
  tasks_.tracking = controller_.taskHandle("tracking");
  tasks_.pose = controller_.taskHandle("pose");
  tasks_.posture = controller_.taskHandle("posture");
}

void CommandLedger::apply(Channel c, const ScopedCommands& v) {
  const ChannelEntry& e = channelEntry(c);
  e.copy(v, current_);
  e.send(controller_, tasks_, current_);
}

void CommandLedger::setGripper(double width, double force) {
  gripper_width_ = width;
  controller_.setGripper(width, force);
}

void CommandLedger::setPayload(double mass, const Vector3& com) {
  payload_set_ = true;
  controller_.setPayload(mass, com);
}

void CommandLedger::clearPayload() {
  payload_set_ = false;
  controller_.clearPayload();
}

void ControllerHandle::change(Channel c, const ScopedCommands& next) {
  const std::uint32_t bit = 1u << static_cast<int>(c);
  if (!(touched_ & bit)) {
    touched_ |= bit;
    channelEntry(c).copy(ledger_->current(), saved_);
  }
  ledger_->apply(c, next);
}

void ControllerHandle::setObservationTarget(ObservationTarget target) {
  ScopedCommands next = ledger_->current();
  next.observation = target;
  change(Channel::kObservation, next);
}

void ControllerHandle::enableTracking(bool on) {
  ScopedCommands next = ledger_->current();
  next.tracking = on;
  change(Channel::kTracking, next);
}

void ControllerHandle::setTrackingOffset(const TrackingOffset& offset) {
  ScopedCommands next = ledger_->current();
  next.tracking_offset = offset;
  change(Channel::kTrackingOffset, next);
}

void ControllerHandle::setPoseTarget(const Isometry& tcp, const Vector6& velocity) {
  ScopedCommands next = ledger_->current();
  next.pose.active = true;
  next.pose.pose = tcp;
  next.pose.velocity = velocity;
  change(Channel::kPose, next);
}

void ControllerHandle::clearPoseTarget() {
  ScopedCommands next = ledger_->current();
  next.pose.active = false;
  change(Channel::kPose, next);
}

void ControllerHandle::setPostureTarget(const Vector7& q, const Vector7& qd, const Vector7& qdd) {
  ScopedCommands next = ledger_->current();
  next.posture.active = true;
  next.posture.q = q;
  next.posture.qd = qd;
  next.posture.qdd = qdd;
  change(Channel::kPosture, next);
}

void ControllerHandle::clearPostureTarget() {
  ScopedCommands next = ledger_->current();
  next.posture.active = false;
  change(Channel::kPosture, next);
}

void ControllerHandle::setSpeedScale(double scale) {
  ScopedCommands next = ledger_->current();
  next.speed_scale = scale < 0.0 ? 0.0 : (scale > 1.0 ? 1.0 : scale);
  change(Channel::kSpeedScale, next);
}

void ControllerHandle::undo() {
  if (!ledger_) return;
  // channels are independent: table order is as good as any
  for (std::size_t c = 0; c < kNumChannels; ++c) {
    if (touched_ & (1u << c)) ledger_->apply(static_cast<Channel>(c), saved_);
  }
  touched_ = 0;
}

void ControllerHandle::setStiffness(Channel c, GainsCommand ScopedCommands::*gains, double translation,
                                    double orientation, double max_speed) {
  ScopedCommands next = ledger_->current();
  (next.*gains) = GainsCommand{true, translation, orientation, max_speed};
  change(c, next);
}

void ControllerHandle::setTrackingStiffness(double translation, double orientation, double max_speed) {
  setStiffness(Channel::kGains, &ScopedCommands::gains, translation, orientation, max_speed);
}

void ControllerHandle::clearStiffness(Channel c, GainsCommand ScopedCommands::*gains) {
  ScopedCommands next = ledger_->current();
  (next.*gains).active = false;
  change(c, next);
}

void ControllerHandle::clearTrackingStiffness() { clearStiffness(Channel::kGains, &ScopedCommands::gains); }

void ControllerHandle::setPoseStiffness(double translation, double orientation) {
  setStiffness(Channel::kPoseGains, &ScopedCommands::pose_gains, translation, orientation);
}

void ControllerHandle::clearPoseStiffness() { clearStiffness(Channel::kPoseGains, &ScopedCommands::pose_gains); }

void ControllerHandle::setTaskEnabled(int task, bool on) {
  if (task < 0 || task >= 32 || task == ledger_->tasks().tracking || task == ledger_->tasks().pose) {
    if (task == ledger_->tasks().tracking && task >= 0) enableTracking(on);
    return;  // pose: setPoseTarget / clearPoseTarget (a pose task needs its target)
  }
  ScopedCommands next = ledger_->current();
  const std::uint32_t bit = 1u << task;
  next.task_switches.mask |= bit;
  next.task_switches.on = on ? (next.task_switches.on | bit) : (next.task_switches.on & ~bit);
  change(Channel::kTaskSwitches, next);
}

void ControllerHandle::anticipateRest(bool on) {
  ScopedCommands next = ledger_->current();
  next.anticipate_rest = on;
  change(Channel::kAnticipation, next);
}

void ControllerHandle::fingersAroundObject(bool around) {
  ScopedCommands next = ledger_->current();
  next.fingers_around_object = around;
  change(Channel::kFingersAround, next);
}

void ControllerHandle::relaxHandClearance(bool relaxed) {
  ScopedCommands next = ledger_->current();
  next.hand_clearance_relaxed = relaxed;
  change(Channel::kHandClearance, next);
}

}  // namespace handover::fsm
