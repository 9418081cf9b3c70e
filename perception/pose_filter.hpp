// Constant-velocity Kalman filter on a rigid pose (SE(3) as position x
// rotation): it estimates where a tracked body is and how fast it moves and
// turns, so a sample that is `age` s old can be predicted forward to now
// (latency compensation), and noise is filtered without the lag of a
// first-order smoothing (which trails a hand moving at 1 m/s by
// v * tau: 3 cm at tau = 30 ms).
//
// Model, per axis of the position and of the rotation error (decoupled and
// alike, so one 2x2 covariance serves the three axes of each):
//   state [x, v], x' = v, v' = white noise of spectral density q
//   (acceleration_noise^2, resp. angular_acceleration_noise^2);
//   measurement x + white noise of std r (position_noise, rotation_noise).
// The rotation is kept as a unit quaternion R with an angular velocity w
// (world axes); the filter works on the error in the tangent space:
// prediction R(t + h) = exp(w h) R(t); innovation log(R_measured R^-1)
// (world-axis rotation vector), correction R <- exp(K0 e) R, w <- w + K1 e.
// Measurement noise: position_noise and rotation_noise are floors; with
// noise_adaptation_time > 0 the filter also estimates the sensor's actual
// noise from the second differences of successive samples (z_k - 2 z_k-1 +
// z_k-2: 6 sigma^2 per axis for white noise, while a hand's own acceleration
// adds only a dt^2, about 1 mm at 60 Hz) and uses the larger, so a noisy
// tracker is smoothed as much as its noise needs and a clean one is not.
// Real-time safe (fixed-size, no allocation). World frame; m, rad, s.
#pragma once

#include <Eigen/Geometry>
#include <cmath>

#include "perception/pose_sample.hpp"

namespace handover::perception {

struct PoseFilterSettings {
  double position_noise = 0.003;   ///< m, std of a measured position, per axis
  double rotation_noise = 1.5 * M_PI / 180.0;  ///< rad, std of each rotation-vector component of a measurement
  /// m/s^1.5: sqrt of the spectral density of the unmodelled (white)
  /// acceleration; larger follows changes of speed faster, filters less.
  double acceleration_noise = 0.15;
  double angular_acceleration_noise = 1.0;  ///< rad/s^1.5, the same for turning
  double initial_speed = 1.0;                ///< m/s, std of the velocity when a track starts (0 assumed)
  double initial_angular_speed = 3.0;        ///< rad/s, the same for turning
  /// s, time constant of the running estimate of the sensor's noise (0 =
  /// use position_noise and rotation_noise as they are).
  double noise_adaptation_time = 1.0;
};

/// Covariance of one axis' [x, v] (the same for each axis).
struct AxisCovariance {
  double xx = 0.0, xv = 0.0, vv = 0.0;
  void predict(double dt, double q);
  /// Correction with a measurement of variance r; the gains of x and v.
  void correct(double r, double& k_x, double& k_v);
};

class PoseFilter {
 public:
  explicit PoseFilter(const PoseFilterSettings& settings = {}) : s_(settings) {}

  /// Starts a track at the measured pose `z` taken at `stamp` (s), at rest.
  void reset(const Pose& z, double stamp);
  /// Predicts to `stamp` (not before the last one) and corrects with `z`.
  void update(const Pose& z, double stamp);
  bool seeded() const { return seeded_; }
  void clear() { seeded_ = false; }

  /// Position expected at time `t` (s, >= stamp()) by constant velocity.
  Eigen::Vector3d position(double t) const { return p_ + v_ * (t - stamp_); }
  /// Pose expected at time `t` (s) by constant velocity and turn rate.
  Pose predict(double t) const { return predict(t, t); }
  /// The same with the position at `t_position` and the rotation at `t_rotation`.
  Pose predict(double t_position, double t_rotation) const;
  /// predict(), with the velocities scaled by their significance s = |v|^2 /
  /// (|v|^2 + k^2 * 3 var(v)) (var from the filter's covariance): a body at
  /// rest, whose estimated velocity is mostly noise, is not pushed around by
  /// it (the prediction's jitter is the velocity's noise times the horizon),
  /// while one that clearly moves is predicted in full. k = 0: plain.
  Pose predict(double t_position, double t_rotation, double k) const;
  const Eigen::Vector3d& velocity() const { return v_; }         ///< m/s, world
  const Eigen::Vector3d& angularVelocity() const { return w_; }  ///< rad/s, world
  double stamp() const { return stamp_; }                          ///< s, of the last measurement
  const AxisCovariance& positionCovariance() const { return pp_; }
  const AxisCovariance& rotationCovariance() const { return pr_; }
  /// The measurement noise in use (std per axis): the floor or the estimate.
  double positionNoise() const;
  double rotationNoise() const;

 private:
  PoseFilterSettings s_;
  bool seeded_ = false;
  double stamp_ = 0.0;
  Eigen::Vector3d p_ = Eigen::Vector3d::Zero(), v_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d w_ = Eigen::Vector3d::Zero();
  AxisCovariance pp_, pr_;
  // the noise estimate: the last two measurements and the running variances (per axis)
  void adaptNoise(const Pose& z, double stamp);
  int history_ = 0;  ///< measurements kept in z1_, z2_ (0..2)
  Pose z1_, z2_;     ///< the previous measurement and the one before
  double t1_ = 0.0, t2_ = 0.0;
  double var_p_ = 0.0, var_r_ = 0.0;  ///< running estimates of the noise variance, m^2 and rad^2 per axis
};

}  // namespace handover::perception
