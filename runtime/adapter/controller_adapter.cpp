#include "runtime/adapter/controller_adapter.hpp"

#include <algorithm>
#include <cmath>

#include "runtime/adapter/tracking_offset_rule.hpp"

namespace handover::runtime {

ControllerAdapter::ControllerAdapter(control::Controller& controller, perception::ObservationTarget& target,
                                     const control::GraspOffset& object_grasp, double open_width)
    : controller_(controller), target_(target), object_grasp_(object_grasp),
      tracking_(controller.taskIndex("tracking")), offset_task_(tracking_),
      placement_{object_grasp.placement, false}, open_width_(open_width), gripper_width_(open_width) {}

void ControllerAdapter::setObservationTarget(fsm::ObservationTarget target) {
  target_kind_ = target;
  // the perception side blends between sources, so the observed state never jumps
  if (target == fsm::ObservationTarget::kObject) target_.select(perception::TargetSource::Object, now_);
  if (target == fsm::ObservationTarget::kHand) target_.select(perception::TargetSource::Hand, now_);
  applyOffset();
}

void ControllerAdapter::setTaskEnabled(int task, bool on) { controller_.setTaskEnabled(task, on); }

void ControllerAdapter::resetTaskEnabled(int task) {
  if (task < 0 || task >= static_cast<int>(controller_.config().tasks.size())) return;
  controller_.setTaskEnabled(task, controller_.config().tasks[task].enabled);
}

void ControllerAdapter::setTaskTarget(int task, const fsm::TaskTarget& target) {
  control::TaskTarget t;
  t.kind = target.kind == fsm::TaskTarget::Kind::kPose     ? control::TaskTarget::Kind::kPose
           : target.kind == fsm::TaskTarget::Kind::kJoints ? control::TaskTarget::Kind::kJoints
                                                           : control::TaskTarget::Kind::kConfigured;
  t.pose = target.pose;
  t.velocity = target.velocity;
  t.q = target.q;
  t.qd = target.qd;
  t.qdd = target.qdd;
  controller_.setTaskTarget(task, t);
}

void ControllerAdapter::setTaskGains(int task, const fsm::TaskGains& gains) {
  control::TaskGains g;
  g.configured = !gains.active;
  if (gains.active) {
    g.translation = control::PdGains::critical(gains.translation);
    g.orientation = control::PdGains::critical(gains.orientation);
    g.max_speed = gains.max_speed;
  }
  controller_.setTaskGains(task, g);
}

void ControllerAdapter::setTaskOffset(int task, const fsm::TrackingOffset& offset) {
  if (task < 0) return;
  offset_task_ = task;
  placement_ = offset;
  applyOffset();
}

void ControllerAdapter::applyOffset() {
  control::GraspOffset g = makeTrackingOffset(placement_.target_in_observed, object_grasp_,
                                              target_kind_ == fsm::ObservationTarget::kObject, placement_.planned,
                                              placement_.joint_plan);
  g.approach_speed = placement_.approach_speed;
  g.approach_acceleration = placement_.approach_acceleration;
  controller_.setTaskOffset(offset_task_, g);
}

void ControllerAdapter::setSpeedScale(double scale) {
  // the controller scales its velocity limits; zero would make the QP hold
  // position abruptly, so keep a small floor (the FSM's stop uses a pose hold)
  speed_scale_ = std::clamp(scale, 0.0, 1.0);
  controller_.setSpeedScale(std::max(speed_scale_, 0.02));
}

void ControllerAdapter::relaxHandClearance(bool relaxed) {
  hand_relaxed_ = relaxed;
  applyClearances();
}

void ControllerAdapter::fingersAroundObject(bool around) {
  fingers_around_ = around;
  applyClearances();
}

void ControllerAdapter::applyClearances() {
  if (collision_ == nullptr) return;
  auto set = [this](int rule, bool on) {
    if (collision_->ruleEnabled(rule) != on) collision_->setRuleEnabled(rule, on);  // a switch resets its dampers
  };
  if (object_rule_ >= 0) set(object_rule_, !hand_relaxed_ && !payload_set_ && !fingers_around_);
  const std::vector<control::RuleScope>& scope = collision_->collisionModel().rule_scope;
  for (int i = 0; i < static_cast<int>(scope.size()); ++i) {
    if (i == object_rule_) continue;
    if (scope[i] == control::RuleScope::kApart) set(i, !hand_relaxed_);
    if (scope[i] == control::RuleScope::kSharing) set(i, hand_relaxed_);
    if (scope[i] == control::RuleScope::kTaking) set(i, hand_relaxed_ && !payload_set_ && !fingers_around_);
  }
}

void ControllerAdapter::placeObservedFrame(const fsm::Isometry& pose) {
  controller_.resetObservedObject(pose);
  controller_.setObservationTarget(pose, true);  // held there until a measurement moves it
}

bool ControllerAdapter::trackingTargetAt(const fsm::Isometry& observed, double wrist_q, fsm::Isometry& tcp) const {
  if (tracking_ < 0 || !observed.matrix().allFinite() || !std::isfinite(wrist_q)) return false;
  const control::Model& m = controller_.model();
  const int w = control::kArmDofs - 1;
  control::ObservedState at_rest;
  at_rest.pose = observed;
  tcp = control::graspFrameState(at_rest, control::Vector6::Zero(), controller_.trackingTask().graspOffset(),
                                 controller_.tcpPose().linear(), wrist_q - 0.5 * (m.q_min[w] + m.q_max[w]))
            .pose;
  return true;
}

void ControllerAdapter::setGripper(double width, double force) {
  gripper_width_ = std::clamp(width, 0.0, open_width_);
  gripper_force_ = std::max(force, 0.0);
}

void ControllerAdapter::setPayload(double mass, const fsm::Vector3& com_in_tcp) {
  control::Payload p;
  p.mass = mass;
  p.com = com_in_tcp;
  controller_.setPayload(p);
  payload_set_ = true;
  applyClearances();
}

void ControllerAdapter::clearPayload() {
  controller_.clearPayload();
  payload_set_ = false;
  applyClearances();
}

}  // namespace handover::runtime
