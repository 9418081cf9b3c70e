// Joint-space disturbance observer: the joint torque the model does not
// explain. Each period, from the torque applied over the last period and the
// motion it caused:
//
//   d = M(q) qdd_meas + h(q, qdot) - tau_applied,   qdd_meas = (qdot - qdot_prev) / dt
//
// low-pass filtered (filter_tau) and clipped per joint to max_torque_fraction
// of its torque limit. It holds what the model gets wrong - where the held
// object's mass really sits in the grip, joint friction and damping - and any
// outside push on the arm. That is why the controller learns it and feeds it
// back only while the robot alone carries the object; while a person may
// touch the gripper or the object the estimate is held and its feedback
// fades (Controller::setDisturbanceFeedback). Why feed it back at all: the
// acceleration-level PD of a wrist joint is a weak
// spring (posture K = 10 / s^2 times joint 7's inertia 0.013 kg m^2 is
// 0.13 N m/rad), and 0.08 N m the model missed held joint 7 0.8 rad short of
// the carry's goal configuration for ever.
//
// Frames: joint space. Units: N m, rad/s, s. Real-time safe after
// construction (no allocation, no exceptions).
#pragma once

#include "config/yaml_reader.hpp"
#include "control/model/model.hpp"

namespace handover::control {

/// config/controller.yaml `disturbance`.
struct DisturbanceSettings {
  /// Whether it is fed back: off, or while the robot alone carries the object
  /// (the same gate and ramp as the wrist wrench's carry feed-forward, which it
  /// then replaces).
  enum class Compensation { kOff, kCarry };
  Compensation compensation = Compensation::kCarry;
  double filter_tau = 0.02;           ///< s, low-pass of the estimate
  double max_torque_fraction = 0.1;   ///< of each joint's torque limit, the most it holds
};

class DisturbanceObserver {
 public:
  /// `period`: s between update() calls.
  DisturbanceObserver(const DisturbanceSettings& settings, const Vector7& tau_max, double period);

  /// Forgets the history (a new run, a jump in the joint state).
  void reset();
  /// One period. `data`: computeAll at this period's (q, qdot); `tau_applied`:
  /// the torque commanded over the last period. The first call only stores
  /// qdot. `learn` false holds the estimate (a person may be touching the
  /// arm or what it holds: their push is no model error). Non-finite input
  /// keeps the last estimate. RT safe.
  void update(const Data& data, const Vector7& qd, const Vector7& tau_applied, bool learn = true);

  /// The filtered, clipped disturbance torque (external, like J^T f), N m.
  const Vector7& torque() const { return estimate_; }
  /// The last period's disturbance, unfiltered and whether learning or not,
  /// clipped to the torque limits (0 before two updates): what acted on the
  /// arm a moment ago, for a one-period prediction (the limit guard), N m.
  const Vector7& latest() const { return latest_; }

 private:
  double period_;
  double alpha_;   ///< filter gain per update
  Vector7 limit_;
  Vector7 estimate_ = Vector7::Zero();
  Vector7 latest_ = Vector7::Zero();
  Vector7 tau_max_ = Vector7::Zero();
  Vector7 qd_prev_ = Vector7::Zero();
  bool have_prev_ = false;
};

/// config/controller.yaml's `disturbance` section; unknown keys and
/// out-of-range values throw InputError naming the file, key and line.
DisturbanceSettings parseDisturbanceSettings(const YamlReader& section);

}  // namespace handover::control
