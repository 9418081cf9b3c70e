#include "perception/pose_filter.hpp"

#include <algorithm>
#include <cmath>

namespace handover::perception {

namespace {
// exp of a world-axis rotation vector, as a quaternion
Eigen::Quaterniond expRotation(const Eigen::Vector3d& v) {
  const double a = v.norm();
  if (a < 1e-12) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(a, v / a));
}
// log of a rotation (shortest way round), as a rotation vector
Eigen::Vector3d logRotation(const Eigen::Quaterniond& q) {
  const Eigen::AngleAxisd aa(q);  // Eigen picks the angle in [0, pi]
  return aa.angle() * aa.axis();
}
}  // namespace

void AxisCovariance::predict(double dt, double q) {
  // P <- F P F^T + q [dt^3/3, dt^2/2; dt^2/2, dt], F = [1 dt; 0 1]
  const double dt2 = dt * dt;
  xx += 2.0 * dt * xv + dt2 * vv + q * dt2 * dt / 3.0;
  xv += dt * vv + q * dt2 / 2.0;
  vv += q * dt;
}

void AxisCovariance::correct(double r, double& k_x, double& k_v) {
  const double s = xx + r;
  k_x = xx / s;
  k_v = xv / s;
  // P <- (I - K H) P, H = [1 0]
  vv -= k_v * xv;
  xv *= 1.0 - k_x;
  xx *= 1.0 - k_x;
}

double PoseFilter::positionNoise() const { return std::sqrt(std::max(s_.position_noise * s_.position_noise, var_p_)); }
double PoseFilter::rotationNoise() const { return std::sqrt(std::max(s_.rotation_noise * s_.rotation_noise, var_r_)); }

void PoseFilter::adaptNoise(const Pose& z, double stamp) {
  if (s_.noise_adaptation_time <= 0.0) return;
  if (history_ >= 2) {
    const double dt1 = stamp - t1_, dt2 = t1_ - t2_;
    // evenly spaced samples only (a dropout or a jittery stream says nothing of the noise)
    if (dt1 > 0.0 && dt2 > 0.0 && std::abs(dt1 - dt2) <= 0.25 * dt2) {
      const Eigen::Vector3d d2p = z.position - 2.0 * z1_.position + z2_.position;
      const Eigen::Vector3d d2r = logRotation(z.orientation * z1_.orientation.conjugate()) -
                                  logRotation(z1_.orientation * z2_.orientation.conjugate());
      const double a = std::min(1.0, dt1 / s_.noise_adaptation_time);
      var_p_ += a * (d2p.squaredNorm() / 18.0 - var_p_);  // 3 axes, 6 sigma^2 each
      var_r_ += a * (d2r.squaredNorm() / 18.0 - var_r_);
    }
  }
  z2_ = z1_;
  t2_ = t1_;
  z1_ = z;
  t1_ = stamp;
  history_ = std::min(history_ + 1, 2);
}

void PoseFilter::reset(const Pose& z, double stamp) {
  seeded_ = true;
  history_ = 0;  // the noise estimate itself is the sensor's: kept
  adaptNoise(z, stamp);
  stamp_ = stamp;
  p_ = z.position;
  v_.setZero();
  q_ = z.orientation.normalized();
  w_.setZero();
  const double rp = positionNoise(), rr = rotationNoise();
  pp_ = {rp * rp, 0.0, s_.initial_speed * s_.initial_speed};
  pr_ = {rr * rr, 0.0, s_.initial_angular_speed * s_.initial_angular_speed};
}

void PoseFilter::update(const Pose& z, double stamp) {
  if (!seeded_) {
    reset(z, stamp);
    return;
  }
  adaptNoise(z, stamp);
  // predict to the measurement's stamp
  const double dt = stamp > stamp_ ? stamp - stamp_ : 0.0;
  p_ += v_ * dt;
  q_ = (expRotation(w_ * dt) * q_).normalized();
  pp_.predict(dt, s_.acceleration_noise * s_.acceleration_noise);
  pr_.predict(dt, s_.angular_acceleration_noise * s_.angular_acceleration_noise);
  stamp_ = stamp > stamp_ ? stamp : stamp_;

  // correct: position
  double kx = 0.0, kv = 0.0;
  const double rp = positionNoise(), rr = rotationNoise();
  pp_.correct(rp * rp, kx, kv);
  const Eigen::Vector3d e = z.position - p_;
  p_ += kx * e;
  v_ += kv * e;
  // rotation: the error in the tangent space, world axes
  pr_.correct(rr * rr, kx, kv);
  const Eigen::Vector3d er = logRotation(z.orientation * q_.conjugate());
  q_ = (expRotation(kx * er) * q_).normalized();
  w_ += kv * er;
}

Pose PoseFilter::predict(double t_position, double t_rotation, double k) const {
  if (k <= 0.0) return predict(t_position, t_rotation);
  const auto significance = [k](const Eigen::Vector3d& v, double var) {
    const double v2 = v.squaredNorm(), n2 = k * k * 3.0 * std::max(var, 0.0);
    return v2 + n2 > 0.0 ? v2 / (v2 + n2) : 0.0;
  };
  Pose out;
  out.position = p_ + significance(v_, pp_.vv) * v_ * (t_position - stamp_);
  out.orientation = (expRotation(significance(w_, pr_.vv) * w_ * (t_rotation - stamp_)) * q_).normalized();
  return out;
}

Pose PoseFilter::predict(double t_position, double t_rotation) const {
  Pose out;
  out.position = p_ + v_ * (t_position - stamp_);
  out.orientation = (expRotation(w_ * (t_rotation - stamp_)) * q_).normalized();
  return out;
}

}  // namespace handover::perception
