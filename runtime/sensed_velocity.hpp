// Velocity of a sensed body from its successive samples (finite difference
// on new samples, first-order low-pass). The state machine uses it to tell
// an offer (coming) from a withdrawal (leaving). Real-time safe.
// World axes; [linear (m/s); angular (rad/s)].
#pragma once

#include <Eigen/Geometry>

namespace handover::runtime {

class SensedVelocity {
 public:
  explicit SensedVelocity(double filter_tau = 0.05) : tau_(filter_tau) {}

  void reset() { have_ = false; v_.setZero(); }

  /// `stamp` is the sample's measurement time; a repeated stamp changes nothing.
  void update(double stamp, const Eigen::Isometry3d& pose) {
    if (have_ && stamp <= stamp_) return;
    if (have_) {
      const double dt = stamp - stamp_;
      Eigen::Matrix<double, 6, 1> raw;
      raw.head<3>() = (pose.translation() - last_.translation()) / dt;
      const Eigen::AngleAxisd d(pose.linear() * last_.linear().transpose());
      raw.tail<3>() = d.axis() * d.angle() / dt;
      const double a = dt / (tau_ + dt);
      v_ += a * (raw - v_);
    }
    last_ = pose;
    stamp_ = stamp;
    have_ = true;
  }
  /// Takes a velocity estimated elsewhere (the perception estimator's motion
  /// model) instead of differencing samples.
  void set(const Eigen::Matrix<double, 6, 1>& v) {
    v_ = v;
    have_ = false;  // a later update() starts afresh
  }
  const Eigen::Matrix<double, 6, 1>& velocity() const { return v_; }

 private:
  double tau_;
  bool have_ = false;
  double stamp_ = 0.0;
  Eigen::Isometry3d last_ = Eigen::Isometry3d::Identity();
  Eigen::Matrix<double, 6, 1> v_ = Eigen::Matrix<double, 6, 1>::Zero();
};

}  // namespace handover::runtime
