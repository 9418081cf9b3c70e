#include "fsm/handover/reach_states.hpp"

#include "fsm/handover/tracking_setup.hpp"

namespace handover::fsm {

Reach::Reach() { declareOutput("Never"); }  // never done; declared so the table can be checked

void Reach::configure(const YamlReader& def) {
  if (def.has("standoff")) standoff_ = readRange(def, "standoff", 0.0, 0.3);
  if (auto f = def.optionalChild("follow")) set_point_ = f->asEnum({"tracking", "set_point"}) == "set_point";
}

void Reach::onStart(HandoverContext& ctx) {
  on_data_ = false;
  last_stamp_ = -1.0;
  ctrl().setGripper(ctx.params->gripper_open_width, ctx.params->gripper_force);
  ctrl().setObservationTarget(ObservationTarget::kObject);
  setStandoff(ctx, ctrl(), false, standoff_);  // the pre-grasp frame on the object
  // until the first sample, the target frame stays on the TCP
  const Isometry target_in_observed = trackedChoice(ctx, false).offset * Eigen::Translation3d(0.0, 0.0, -standoff_);
  ctrl().placeObservedFrame(ctx.in.tcp_pose * target_in_observed.inverse());
  if (set_point_) {
    ctrl().enableTracking(false);
    ctrl().setPoseTarget(ctx.in.tcp_pose);
  } else {
    ctrl().enableTracking(true);
  }
}

bool Reach::onRun(HandoverContext& ctx) {
  const SensedBody& object = ctx.in.object;
  if (!object.valid) return false;
  if (!on_data_) {
    ctrl().placeObservedFrame(object.pose);
    on_data_ = true;
  }
  if (set_point_ && object.stamp != last_stamp_) {
    last_stamp_ = object.stamp;
    Isometry tcp;
    if (ctrl().trackingTargetAt(object.pose, ctx.in.q[6], tcp)) ctrl().setPoseTarget(tcp);
  }
  return false;
}

Hold::Hold() { declareOutput("Never"); }

void Hold::configure(const YamlReader& def) {
  if (auto p = def.optionalChild("posture")) posture_ = p->asVector(7);
  if (auto p = def.optionalChild("pose")) pose_ = readPose(*p);
}

void Hold::onStart(HandoverContext& ctx) {
  (void)ctx;
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(ObservationTarget::kNone);
  if (pose_) ctrl().setPoseTarget(*pose_);
  else ctrl().clearPoseTarget();
  if (posture_) ctrl().setPostureTarget(*posture_);
}

bool Hold::onRun(HandoverContext& ctx) {
  (void)ctx;
  return false;
}

}  // namespace handover::fsm
