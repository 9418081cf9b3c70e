// The physical exchange, as the wrist force-torque sensor feels it: what the
// gripper holds (the object, and through it the person) pushes on the robot.
// Each control cycle (paper: M qdd + N = tau + J_c^T f):
//
//   1. compensate  reading - sensor offset (FtBiasCalibrator) - the tool's
//                  weight and inertia (Model::tool, turning with the wrist,
//                  accelerating with the sensor: the model's acceleration)
//   2. world       rotate into world axes: force, and torque about the sensor
//   3. filter      first-order low-pass (filter_tau)
//   4. load share  s = (filtered force along gravity) / (m g), clipped to
//                  0..1, and 0 while the gripper is open: 0 while the person
//                  carries the object, 1 once the robot does
//   5. payload     the object's mass properties scaled by s: the model carries
//                  the share the robot holds (with its inertia)
//   6. feed-forward  the filtered load minus what that payload already puts in
//                  the model (its weight and inertial force): the rest is the
//                  known external wrench the dynamics hold (Controller::
//                  setExternalWrench). Mode `carry`: only while the robot
//                  carries the object alone - then the rest is the model's
//                  error about the object (where its mass really sits in the
//                  grip), which otherwise turns the wrist: its joints' small
//                  inertia makes the acceleration-level gains a weak spring
//                  (0.06 N m held joint 7 0.6 rad off its goal). While a
//                  person shares the object the rest is their force, and
//                  feeding back a force the robot's own push causes through a
//                  rigid grip would push harder (mode `always`, kept for
//                  experiments). Switching ramps over ramp_time.
//
// Frames: world (z up) unless said; the wrench is [force (N); torque (N m)
// about the "ft_sensor" origin]. Real-time safety: update() and the
// read-outs allocate nothing and never throw; the constructor and start()
// are start-up calls.
#pragma once

#include "config/yaml_reader.hpp"
#include "control/model/model.hpp"
#include "control/wrench/ft_bias.hpp"

namespace handover::control {

/// config/controller.yaml `contact_wrench`.
struct ContactWrenchSettings {
  enum class FeedForward { kOff, kCarry, kAlways };
  /// When the rest of the load goes to the dynamics (off: estimate and log only; docs/method.md).
  FeedForward feed_forward = FeedForward::kCarry;
  double ramp_time = 0.2;         ///< s, the feed-forward fades in and out over this
  /// m: a person's grip point this close to the TCP may be holding the object (no carry feed-forward).
  double shared_distance = 0.15;
  double filter_tau = 0.01;       ///< s, low-pass time constant of the load
  double calibration_time = 0.2;  ///< s of readings at rest that calibrate the sensor offset
  double rest_speed = 0.02;       ///< rad/s, joint speed norm below which the arm is at rest
};

/// What the estimator reads each cycle.
struct ContactWrenchInput {
  Vector6 reading = Vector6::Zero();            ///< io::ArmState::wrench, sensor frame
  Matrix3 sensor_rotation = Matrix3::Identity();///< the sensor's axes in the world
  Vector3 sensor_acceleration = Vector3::Zero();///< m/s^2, world, of the sensor origin (the model's)
  bool at_rest = false;                         ///< the arm is still (calibration samples)
  bool gripper_closed = false;                  ///< the fingers are commanded closed (may hold the object)
  bool carried_alone = false;                   ///< the robot alone carries the object (mode carry)
};

class ContactWrenchEstimator {
 public:
  /// `period`: s between update() calls. Not RT safe.
  ContactWrenchEstimator(const Model& model, const ContactWrenchSettings& settings, double period);

  /// Start of a run: `object` = what may be held (mass kg, com in the "tcp"
  /// frame); `holds` = the gripper starts holding it, so the calibration
  /// counts its weight (known mass) with the tool's, and the load share
  /// starts at 1. Restarts the calibration and the filter. The calibration
  /// takes readings at rest until it has calibration_time of them or the
  /// gripper leaves its start state (opened or closed); until then the
  /// offset is zero (the model's tool weight alone).
  void start(const Payload& object, bool holds);

  /// What may be held changes (a grasp chosen while approaching moves the
  /// centre of mass in the tcp frame); the calibration stays. RT safe.
  void setObject(const Payload& object) { object_ = object; }

  /// One cycle. Non-finite readings keep the last estimate. RT safe.
  void update(const ContactWrenchInput& in);

  /// Filtered wrench that what the gripper holds exerts on the robot, world axes.
  const Vector6& load() const { return load_; }
  /// 0 (the person carries the object) .. 1 (the robot does).
  double loadShare() const { return share_; }
  /// Filtered force on the sensor beyond the tool and the whole object as if
  /// the robot alone carried it (its weight and its inertial force at the
  /// sensor's acceleration), world axes, N: what a person holding, pushing
  /// or pulling the object adds. The object's inertia is taken out before
  /// the filter, so the arm's own accelerations (braking into a
  /// presentation) do not read as a pull. Meaningful while the fingers are
  /// closed on the object; with them open it is the load itself.
  const Vector3& interactionForce() const { return interaction_; }
  /// The object scaled by the load share, for the model (tcp frame).
  const Payload& payload() const { return payload_; }
  /// The known external wrench on the robot at the sensor, world axes: the
  /// load minus what payload() puts in the model. Zero when feed_forward is
  /// off and until the offset is calibrated.
  const Vector6& feedForward() const { return feed_forward_; }
  /// 0..1: the feed-forward's ramp (1 while the robot alone carries the
  /// object in mode carry, once the sensor is calibrated).
  double feedForwardGain() const { return ff_gain_; }
  /// 0..1: the joint disturbance feedback's ramp (1 while the robot alone
  /// carries the object; Controller::setDisturbanceFeedback). It needs no
  /// sensor calibration: a give starts moving at once, before the arm ever
  /// rests long enough to calibrate, and its wrist needs the feedback most.
  double disturbanceGain() const { return disturbance_gain_; }
  bool calibrated() const { return calibrator_.done(); }
  const FtBiasCalibrator& calibrator() const { return calibrator_; }
  const ContactWrenchSettings& settings() const { return settings_; }

 private:
  Inertia objectInSensor(double share) const;

  ContactWrenchSettings settings_;
  Inertia tool_;              ///< sensor frame
  Isometry sensor_T_tcp_;
  Vector3 gravity_;
  double alpha_;              ///< filter gain per update
  FtBiasCalibrator calibrator_;
  Payload object_;            ///< tcp frame
  Inertia held_at_start_;     ///< sensor frame: tool (+ object) during the calibration
  bool holds_at_start_ = false;
  bool calibrating_ = true;   ///< until the gripper leaves its start state
  bool filtered_ = false;
  Vector6 load_ = Vector6::Zero();
  Vector3 interaction_ = Vector3::Zero();
  double share_ = 0.0;
  Payload payload_;
  Vector6 feed_forward_ = Vector6::Zero();
  double ff_gain_ = 0.0;      ///< 0..1, the feed-forward's ramp
  double disturbance_gain_ = 0.0;  ///< 0..1, the disturbance feedback's ramp
  double ff_step_ = 1.0;      ///< gain change per update (period / ramp_time)
};

/// config/controller.yaml's `contact_wrench` section (optional; defaults
/// above); unknown keys and out-of-range values throw InputError naming the
/// file, key and line.
ContactWrenchSettings parseContactWrenchSettings(const YamlReader& section);

}  // namespace handover::control
