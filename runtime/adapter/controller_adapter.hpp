// The state machine's view of the QP controller (fsm::ControllerInterface),
// implemented over control::Controller and perception::ObservationTarget:
// the one place where fsm/ meets control/ (its own library, handover_adapter).
// Every call stores a set-point applied at the next control step; all calls
// are real-time safe (no allocation, no exceptions).
//
// Frames: world; TCP offsets in the observed object's frame; SI units.
#pragma once

#include <string>

#include "control/constraints/collision_constraint.hpp"
#include "control/controller.hpp"
#include "fsm/handover/controller_interface.hpp"
#include "perception/observation_target.hpp"

namespace handover::runtime {

class ControllerAdapter : public fsm::ControllerInterface {
 public:
  /// `grasp_free_axis`: the object's symmetry axis (object frame) if it has
  /// one; the tracking offset then keeps that freedom (nearest grasp).
  ControllerAdapter(control::Controller& controller, perception::ObservationTarget& target,
                    const control::GraspOffset& object_grasp, double open_width);

  /// Time of the current cycle (blends of the observation target start then).
  void setTime(double t) { now_ = t; }

  // tasks by handle = the controller's task index (config/controller.yaml order)
  int taskHandle(const std::string& name) const override { return controller_.taskIndex(name); }
  void setTaskEnabled(int task, bool on) override;
  void resetTaskEnabled(int task) override;
  void setTaskTarget(int task, const fsm::TaskTarget& target) override;
  /// Critically damped gains from the stiffnesses (inactive: configured).
  void setTaskGains(int task, const fsm::TaskGains& gains) override;
  /// Through the tracking-offset rule (tracking_offset_rule.hpp): the
  /// object's grasp with its symmetry while the object is observed.
  void setTaskOffset(int task, const fsm::TrackingOffset& offset) override;

  void setObservationTarget(fsm::ObservationTarget target) override;
  void setSpeedScale(double scale) override;
  void relaxHandClearance(bool relaxed) override;
  void fingersAroundObject(bool around) override;
  void anticipateRest(bool on) override { anticipate_ = on; }
  /// The collision constraint whose scoped rules (`when: apart | sharing`,
  /// control/collision/collision_config.hpp) follow the state machine's
  /// hand-clearance switch; none: relaxHandClearance does nothing.
  /// `object_rule` (gripper and the object the person holds) is on while
  /// the gripper approaches: off while sharing and while a payload is set.
  void setCollision(control::CollisionConstraint* collision, int object_rule = -1) {
    collision_ = collision;
    object_rule_ = object_rule;
    applyClearances();
  }
  /// Controller::resetObservedObject there, and the observation target with it.
  void placeObservedFrame(const fsm::Isometry& pose) override;
  /// control::graspFrameState of the tracking task's offset at rest, at the
  /// controller's last TCP orientation; `wrist_q` from the middle of its range.
  bool trackingTargetAt(const fsm::Isometry& observed, double wrist_q, fsm::Isometry& tcp) const override;
  void setGripper(double width, double force) override;
  void setPayload(double mass, const fsm::Vector3& com_in_tcp) override;
  void clearPayload() override;

  fsm::ObservationTarget observationTarget() const { return target_kind_; }
  bool payloadSet() const { return payload_set_; }
  /// The state machine says the person's hand and the gripper share the object.
  bool handClearanceRelaxed() const { return hand_relaxed_; }
  /// The state machine asks to meet the person where the reach will end.
  bool anticipatingRest() const { return anticipate_; }
  double gripperWidth() const { return gripper_width_; }
  double gripperForce() const { return gripper_force_; }
  /// The "tracking" task is on.
  bool trackingEnabled() const { return controller_.taskEnabled(tracking_); }
  double speedScale() const { return speed_scale_; }
  /// The tracking target in the observed frame, as last set.
  const fsm::Isometry& trackingOffset() const { return placement_.target_in_observed; }
  /// The tracking offset is a planned choice (tracked exactly).
  bool trackingOffsetPlanned() const { return placement_.planned; }

 private:
  void applyOffset();
  void applyClearances();
  control::Controller& controller_;
  perception::ObservationTarget& target_;
  control::GraspOffset object_grasp_;
  int tracking_ = -1;              ///< the "tracking" task's index
  int offset_task_ = -1;           ///< the task the last offset went to (re-applied on an observation switch)
  fsm::TrackingOffset placement_;  ///< its target in the observed frame
  fsm::ObservationTarget target_kind_ = fsm::ObservationTarget::kNone;
  bool anticipate_ = false;
  double now_ = 0.0;
  bool payload_set_ = false;
  double open_width_;  ///< m, the gripper's widest opening (commands are clamped to it)
  double gripper_width_;
  double gripper_force_ = 40.0;
  double speed_scale_ = 1.0;
  control::CollisionConstraint* collision_ = nullptr;
  int object_rule_ = -1;
  bool fingers_around_ = false;  ///< the fingers are around the person's object: object and `taking` rules off
  bool hand_relaxed_ = false;
};

}  // namespace handover::runtime
