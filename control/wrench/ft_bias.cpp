#include "control/wrench/ft_bias.hpp"

namespace handover::control {

Vector6 hangingWrench(const Inertia& body, const Matrix3& R, const Vector3& gravity) {
  Vector6 w;
  const Vector3 f = body.mass * (R.transpose() * gravity);
  w.head<3>() = f;
  w.tail<3>() = body.com.cross(f);
  return w;
}

void FtBiasCalibrator::restart() {
  count_ = 0;
  sum_.setZero();
  offset_.setZero();
}

void FtBiasCalibrator::add(const Vector6& reading, const Matrix3& R, const Inertia& hanging,
                           const Vector3& gravity) {
  if (done() || !reading.allFinite() || !R.allFinite()) return;
  sum_ += reading - hangingWrench(hanging, R, gravity);
  ++count_;
  if (done()) offset_ = sum_ / count_;
}

}  // namespace handover::control
