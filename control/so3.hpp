// Small SO(3) helpers shared by the tasks and the observed-object integrator.
// Header-only, allocation-free, real-time safe. Rotation vectors are in world
// axes unless a function says otherwise; angles in rad.
#pragma once

#include <cmath>

#include "control/types.hpp"

namespace handover::control {

/// [v]x such that skew(v) * w = v.cross(w).
inline Matrix3 skew(const Vector3& v) {
  Matrix3 S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

/// Rotation vector (axis * angle, angle in [0, pi]) of a rotation matrix.
inline Vector3 logRotation(const Matrix3& R) {
  Quaternion q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // shortest rotation
  const double n = q.vec().norm();
  if (n < 1e-12) return 2.0 * q.vec();         // first order near identity
  return (2.0 * std::atan2(n, q.w()) / n) * q.vec();
}

/// Rotation matrix of a rotation vector (exponential map).
inline Matrix3 expRotation(const Vector3& w) {
  const double angle = w.norm();
  if (angle < 1e-12) return Matrix3::Identity() + skew(w);
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

/// The paper's orientation error q_a (-) q_b: rotation vector of R_a R_b^T in
/// world axes. Zero when the frames agree; for small errors its time
/// derivative is omega_a - omega_b (world axes).
inline Vector3 orientationError(const Matrix3& R_a, const Matrix3& R_b) {
  return logRotation(R_a * R_b.transpose());
}

}  // namespace handover::control
