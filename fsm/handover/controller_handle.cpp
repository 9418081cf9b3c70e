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

void CommandLedger::apply(Channel c, const ScopedCommands& v) {
  ControllerInterface& ctl = controller_;
  switch (c) {
    case Channel::kObservation:
      current_.observation = v.observation;
      ctl.setObservationTarget(v.observation);
      break;
    case Channel::kTracking:
      current_.tracking = v.tracking;
      ctl.enableTracking(v.tracking);
      break;
    case Channel::kTrackingOffset:
      current_.tracking_offset = v.tracking_offset;
      ctl.setTrackingOffset(v.tracking_offset);
      break;
    case Channel::kPose:
      current_.pose_active = v.pose_active;
      current_.pose = v.pose;
      if (v.pose_active) ctl.setPoseTarget(v.pose);
      else ctl.clearPoseTarget();
      break;
    case Channel::kPosture:
      current_.posture_active = v.posture_active;
      current_.posture = v.posture;
      if (v.posture_active) ctl.setPostureTarget(v.posture);
      else ctl.clearPostureTarget();
      break;
    case Channel::kSpeedScale:
      current_.speed_scale = v.speed_scale;
      ctl.setSpeedScale(v.speed_scale);
      break;
    case Channel::kGains:
      current_.gains_active = v.gains_active;
      current_.gains_translation = v.gains_translation;
      current_.gains_orientation = v.gains_orientation;
      if (v.gains_active) ctl.setTrackingStiffness(v.gains_translation, v.gains_orientation);
      else ctl.clearTrackingStiffness();
      break;
    case Channel::kHandClearance:
      current_.hand_clearance_relaxed = v.hand_clearance_relaxed;
      ctl.relaxHandClearance(v.hand_clearance_relaxed);
      break;
  }
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

namespace {
// copies one channel's fields only, so earlier saves of other channels survive
void copyChannel(Channel c, const ScopedCommands& from, ScopedCommands& to) {
  switch (c) {
    case Channel::kObservation: to.observation = from.observation; break;
    case Channel::kTracking: to.tracking = from.tracking; break;
    case Channel::kTrackingOffset: to.tracking_offset = from.tracking_offset; break;
    case Channel::kPose:
      to.pose_active = from.pose_active;
      to.pose = from.pose;
      break;
    case Channel::kPosture:
      to.posture_active = from.posture_active;
      to.posture = from.posture;
      break;
    case Channel::kSpeedScale: to.speed_scale = from.speed_scale; break;
    case Channel::kGains:
      to.gains_active = from.gains_active;
      to.gains_translation = from.gains_translation;
      to.gains_orientation = from.gains_orientation;
      break;
    case Channel::kHandClearance: to.hand_clearance_relaxed = from.hand_clearance_relaxed; break;
  }
}
}  // namespace

void ControllerHandle::change(Channel c, const ScopedCommands& next) {
  const std::uint32_t bit = 1u << static_cast<int>(c);
  if (!(touched_ & bit)) {
    touched_ |= bit;
    copyChannel(c, ledger_->current(), saved_);
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

void ControllerHandle::setTrackingOffset(const Isometry& offset) {
  ScopedCommands next = ledger_->current();
  next.tracking_offset = offset;
  change(Channel::kTrackingOffset, next);
}

void ControllerHandle::setPoseTarget(const Isometry& tcp) {
  ScopedCommands next = ledger_->current();
  next.pose_active = true;
  next.pose = tcp;
  change(Channel::kPose, next);
}

void ControllerHandle::clearPoseTarget() {
  ScopedCommands next = ledger_->current();
  next.pose_active = false;
  change(Channel::kPose, next);
}

void ControllerHandle::setPostureTarget(const Vector7& q) {
  ScopedCommands next = ledger_->current();
  next.posture_active = true;
  next.posture = q;
  change(Channel::kPosture, next);
}

void ControllerHandle::clearPostureTarget() {
  ScopedCommands next = ledger_->current();
  next.posture_active = false;
  change(Channel::kPosture, next);
}

void ControllerHandle::setSpeedScale(double scale) {
  ScopedCommands next = ledger_->current();
  next.speed_scale = scale < 0.0 ? 0.0 : (scale > 1.0 ? 1.0 : scale);
  change(Channel::kSpeedScale, next);
}

void ControllerHandle::undo() {
  if (!ledger_) return;
  // newest channels first is not needed: channels are independent
  for (int c = 0; c <= static_cast<int>(Channel::kSpeedScale); ++c) {
    if (touched_ & (1u << c)) ledger_->apply(static_cast<Channel>(c), saved_);
  }
  touched_ = 0;
}

void ControllerHandle::setTrackingStiffness(double translation, double orientation) {
  ScopedCommands next = ledger_->current();
  next.gains_active = true;
  next.gains_translation = translation;
  next.gains_orientation = orientation;
  change(Channel::kGains, next);
}

void ControllerHandle::clearTrackingStiffness() {
  ScopedCommands next = ledger_->current();
  next.gains_active = false;
  change(Channel::kGains, next);
}

void ControllerHandle::relaxHandClearance(bool relaxed) {
  ScopedCommands next = ledger_->current();
  next.hand_clearance_relaxed = relaxed;
  change(Channel::kHandClearance, next);
}

}  // namespace handover::fsm
