#include "control/tasks/observed_object_integrator.hpp"

#include "control/so3.hpp"

namespace handover::control {

void ObservedObjectIntegrator::reset(const Isometry& pose, const Vector6& velocity) {
  state_.pose = pose;
  state_.velocity = velocity;
  state_.acceleration.setZero();
}

void ObservedObjectIntegrator::integrate(const Vector6& acceleration, double dt) {
  const Vector6 a = acceleration.allFinite() ? acceleration : Vector6::Zero();
  const Vector6 v0 = state_.velocity;
  const Vector6 v1 = v0 + a * dt;
  // mean velocity over the step: exact for constant acceleration
  state_.pose.translation() += 0.5 * (v0.head<3>() + v1.head<3>()) * dt;
  const Matrix3 dR = expRotation(0.5 * (v0.tail<3>() + v1.tail<3>()) * dt);
  Matrix3 R = dR * state_.pose.linear();
  // keep R orthonormal over long runs
  const Quaternion q = Quaternion(R).normalized();
  state_.pose.linear() = q.toRotationMatrix();
  state_.velocity = v1;
  state_.acceleration = a;
}

}  // namespace handover::control
