// "A state removes from the QP what it added." Every controller call of a
// state goes through its ControllerHandle. The shared CommandLedger knows the
// current value of each scoped channel; the first time a state changes a
// channel, its handle saves the value it found, and undo() (called from
// teardown, whatever ended the state) puts exactly the touched channels back.
// Nested states therefore restore their parent's settings.
//
// Scoped channels: the rows of channelTable() (scoped_commands.hpp); the
// ledger and the handle loop over that table. Persistent commands (gripper, payload)
// pass straight through and are never undone: a state's end must not open
// the hand on a held object.
// Real-time: every method is RT safe (fixed-size storage).
#pragma once

#include <cstdint>
#include <string>

#include "fsm/handover/controller_interface.hpp"
#include "fsm/handover/scoped_commands.hpp"

namespace handover::fsm {

/// The controller as seen by all states, with the current scoped values.
class CommandLedger {
 public:
  /// Resolves the handles of the tasks the named channels address.
  explicit CommandLedger(ControllerInterface& controller);
  const ScopedCommands& current() const { return current_; }
  /// Writes `value`'s channel `c` (that member only) to the controller and records it.
  void apply(Channel c, const ScopedCommands& value);
  ControllerInterface& controller() { return controller_; }
  const TaskHandles& tasks() const { return tasks_; }
  // persistent state, for queries (e.g. "is a payload set")
  double gripperWidth() const { return gripper_width_; }
  bool payloadSet() const { return payload_set_; }
  void setGripper(double width, double force);
  void setPayload(double mass, const Vector3& com);
  void clearPayload();

 private:
  ControllerInterface& controller_;
  TaskHandles tasks_;
  ScopedCommands current_;
  double gripper_width_ = -1.0;  ///< -1 = never commanded
  bool payload_set_ = false;
};

class ControllerHandle {
  static_assert(kNumChannels <= 32, "touched_ holds one bit per channel");

 public:
  void bind(CommandLedger* ledger) { ledger_ = ledger; }
  bool bound() const { return ledger_ != nullptr; }

  void setObservationTarget(ObservationTarget target);
  void enableTracking(bool on);
  void setTrackingOffset(const TrackingOffset& offset);
  /// A fixed offset the controller may still resolve (free axis, twin).
  void setTrackingOffset(const Isometry& target_in_observed) { setTrackingOffset(TrackingOffset{target_in_observed, false}); }
  /// The pose task's set-point (world) and its own velocity ([m/s; rad/s],
  /// world axes; zero: a fixed set-point), fed forward.
  void setPoseTarget(const Isometry& tcp_in_world, const Vector6& velocity = Vector6::Zero());
  void clearPoseTarget();
  /// The posture task's reference (rad) and its motion (rad/s, rad/s^2; zero:
  /// a fixed reference), fed forward.
  void setPostureTarget(const Vector7& q, const Vector7& qd = Vector7::Zero(), const Vector7& qdd = Vector7::Zero());
  void clearPostureTarget();
  void setSpeedScale(double scale);
  /// The tracking task's stiffnesses (1/s^2, critically damped) and the
  /// fastest (m/s) its PD may ask the TCP to close in (0: as configured).
  void setTrackingStiffness(double translation, double orientation, double max_speed = 0.0);
  void clearTrackingStiffness();
  /// The pose task's stiffnesses (1/s^2, critically damped) for this state.
  void setPoseStiffness(double translation, double orientation);
  /// Back to the pose task's configured stiffnesses.
  void clearPoseStiffness();
  void relaxHandClearance(bool relaxed);
  /// The fingers are around the object the person holds (ControllerInterface::fingersAroundObject).
  void fingersAroundObject(bool around);
  /// Targets where the person's reach will end (ControllerInterface::anticipateRest).
  void anticipateRest(bool on);
  /// Any task by name (config/controller.yaml `tasks:`): its handle, -1 if
  /// none (compares strings: resolve once, e.g. in onStart), and a scoped
  /// on/off switch (handles 0..31; tracking and pose have their own calls above).
  int taskHandle(const std::string& name) const { return ledger_->controller().taskHandle(name); }
  void setTaskEnabled(int task, bool on);

  /// Unscoped, straight to the controller (ControllerInterface): the observed frame.
  void placeObservedFrame(const Isometry& pose) { ledger_->controller().placeObservedFrame(pose); }
  bool trackingTargetAt(const Isometry& observed, double wrist_q, Isometry& tcp) const {
    return ledger_->controller().trackingTargetAt(observed, wrist_q, tcp);
  }

  void setGripper(double width, double force) { ledger_->setGripper(width, force); }
  void setPayload(double mass, const Vector3& com) { ledger_->setPayload(mass, com); }
  void clearPayload() { ledger_->clearPayload(); }

  /// Restores every channel this handle changed since the last undo(), in
  /// table order.
  void undo();
  bool touched(Channel c) const { return (touched_ >> static_cast<int>(c)) & 1u; }
  const CommandLedger& ledger() const { return *ledger_; }

 private:
  /// Saves the ledger's value of `c` on first touch, then applies `next`.
  void change(Channel c, const ScopedCommands& next);
  /// Activates the gains member `gains` (channel `c`) with these stiffnesses.
  void setStiffness(Channel c, GainsCommand ScopedCommands::*gains, double translation, double orientation,
                    double max_speed = 0.0);
  /// Deactivates it: the task's configured stiffnesses again.
  void clearStiffness(Channel c, GainsCommand ScopedCommands::*gains);
  CommandLedger* ledger_ = nullptr;
  ScopedCommands saved_;
  std::uint32_t touched_ = 0;
};

}  // namespace handover::fsm
