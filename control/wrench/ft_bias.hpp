// Bias of the wrist force-torque sensor: what it reads with nothing but the
// gripper (and, if known, a held object) below it. The reading is modelled as
//
//   reading(R) = offset + hangingWrench(body, R, g)
//
// a constant offset (the sensor's own zero error) plus the weight of the body
// hanging below it, which turns with the wrist. The calibration averages
// reading - hangingWrench over samples taken at rest, so the offset it finds
// stays right when the wrist later turns (the weight term follows R).
//
// Wrench convention: io::ArmState::wrench, [force (N); torque (N m) about the
// sensor origin] that the hand exerts on the flange, in the "ft_sensor" frame.
// Real-time safety: everything here allocates nothing and never throws.
#pragma once

#include "control/model/model.hpp"

namespace handover::control {

/// Wrench (sensor frame) that a rigid body hanging still below the sensor
/// exerts on it: its weight m g at its centre of mass. `body`: mass
/// properties in the sensor frame; `R`: sensor axes in the world; `gravity`:
/// world, m/s^2 (0, 0, -9.81). Pass `gravity - a` for a body whose centre of
/// mass accelerates with `a` (world, m/s^2; its rotation is neglected).
Vector6 hangingWrench(const Inertia& body, const Matrix3& R, const Vector3& gravity);

/// The sensor's constant offset, averaged over `samples` readings at rest.
class FtBiasCalibrator {
 public:
  explicit FtBiasCalibrator(int samples = 200) : samples_(samples < 1 ? 1 : samples) {}

  /// Forgets the samples and the offset.
  void restart();
  /// One reading (sensor frame) with `hanging` (sensor frame) below the
  /// sensor, the sensor axes at `R` in the world, the arm at rest. Ignored
  /// once done() or when not finite.
  void add(const Vector6& reading, const Matrix3& R, const Inertia& hanging, const Vector3& gravity);

  bool done() const { return count_ >= samples_; }
  int count() const { return count_; }
  /// The offset (sensor frame); zero until done().
  const Vector6& offset() const { return offset_; }
  /// Reading minus the offset and the weight of `hanging`: what anything
  /// else exerts on the hand, sensor frame.
  Vector6 compensate(const Vector6& reading, const Matrix3& R, const Inertia& hanging, const Vector3& gravity) const {
    return reading - offset_ - hangingWrench(hanging, R, gravity);
  }

 private:
  int samples_;
  int count_ = 0;
  Vector6 sum_ = Vector6::Zero();
  Vector6 offset_ = Vector6::Zero();
};

}  // namespace handover::control
