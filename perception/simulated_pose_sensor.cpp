#include "perception/simulated_pose_sensor.hpp"

#include <cmath>

namespace handover::perception {

SimulatedPoseSensor::SimulatedPoseSensor(const SensorSettings& settings, std::uint64_t seed)
    : settings_(settings), rng_(seed), period_(1.0 / settings.rate_hz) {
  // samples in flight at once: latency / period, plus slack for call jitter
  const auto capacity = static_cast<std::size_t>(std::ceil(settings.latency * settings.rate_hz)) + 8;
  queue_.resize(capacity);
}

bool SimulatedPoseSensor::inDropout(double t) const {
  for (const auto& d : settings_.dropouts) {
    if (t >= d.first && t < d.second) return true;
  }
  return false;
}

Pose SimulatedPoseSensor::corrupt(const Eigen::Isometry3d& truth) {
  const double sp = settings_.noise_pos;
  const double sr = settings_.noise_rot_deg * M_PI / 180.0;
  const Eigen::Vector3d dp(sp * normal_(rng_), sp * normal_(rng_), sp * normal_(rng_));
  const Eigen::Vector3d dr(sr * normal_(rng_), sr * normal_(rng_), sr * normal_(rng_));
  Pose p;
  p.position = truth.translation() + settings_.offset.translation() + dp;
  Eigen::Matrix3d R = truth.rotation() * settings_.offset.rotation();
  const double angle = dr.norm();
  if (angle > 0.0) R = R * Eigen::AngleAxisd(angle, dr / angle).toRotationMatrix();
  p.orientation = Eigen::Quaterniond(R).normalized();
  return p;
}

void SimulatedPoseSensor::observe(double t, const io::HumanBodyPoses& truth) {
  // a small tolerance so that t = k * period computed in floating point counts
  if (t + 1e-9 < static_cast<double>(next_index_) * period_) return;
  // skip sample times missed by a coarse caller: one measurement per call
  next_index_ = static_cast<long>(std::floor(t / period_ + 1e-9)) + 1;
  if (inDropout(t)) return;
  PoseSample s;
  s.stamp = t;
  s.hand = corrupt(truth.hand);
  s.forearm = corrupt(truth.forearm);
  s.upper_arm = corrupt(truth.upper_arm);
  ++measured_;
  if (count_ == queue_.size()) {
    ++overflowed_;
    return;
  }
  queue_[(head_ + count_) % queue_.size()] = s;
  ++count_;
}

bool SimulatedPoseSensor::poll(double now, PoseSample& out) {
  if (count_ == 0) return false;
  const PoseSample& s = queue_[head_];
  if (now + 1e-9 < s.stamp + settings_.latency) return false;
  out = s;
  head_ = (head_ + 1) % queue_.size();
  --count_;
  return true;
}

}  // namespace handover::perception
