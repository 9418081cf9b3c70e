#include "perception/perception_estimator.hpp"

#include <cmath>

namespace handover::perception {

PerceptionEstimator::PerceptionEstimator(const EstimatorSettings& settings) : settings_(settings) {}

void PerceptionEstimator::reset() {
  have_ = false;
  est_ = PerceptionEstimate{};
  rejected_ = 0;
}

bool PerceptionEstimator::addSample(const PoseSample& s, double arrival) {
  if (!s.allFinite() || (have_ && s.stamp < latest_.stamp)) {
    ++rejected_;
    return false;
  }
  const double tau_rot = settings_.rotation_smoothing_time >= 0.0 ? settings_.rotation_smoothing_time
                                                                     : settings_.smoothing_time;
  if (have_ && (settings_.smoothing_time > 0.0 || tau_rot > 0.0)) {
    const double dt = s.stamp - latest_.stamp;
    const auto weight = [dt](double tau) { return tau > 0.0 ? 1.0 - std::exp(-dt / tau) : 1.0; };
    const double a = weight(settings_.smoothing_time), b = weight(tau_rot);
    const auto blend = [a, b](Pose& into, const Pose& sample) {
      into.position += a * (sample.position - into.position);
      into.orientation = into.orientation.slerp(b, sample.orientation).normalized();
    };
    blend(latest_.hand, s.hand);
    blend(latest_.forearm, s.forearm);
    blend(latest_.upper_arm, s.upper_arm);
    if (s.has_object && latest_.has_object) blend(latest_.object, s.object);
    else latest_.object = s.object;
    latest_.has_object = s.has_object;
    latest_.stamp = s.stamp;
  } else {
    latest_ = s;
  }
  arrival_ = arrival;
  have_ = true;
  return true;
}

int PerceptionEstimator::update(double now, PoseSource& source) {
  int n = 0;
  PoseSample s;
  while (source.poll(now, s)) n += addSample(s, now) ? 1 : 0;
  return n;
}

const PerceptionEstimate& PerceptionEstimator::estimate(double now, ObjectHolder holder,
                                                        const Eigen::Isometry3d& tcp_pose,
                                                        const Eigen::Isometry3d& tcp_T_object) {
  est_.time = now;
  HumanEstimate& h = est_.human;
  h.valid = have_;
  if (have_) {
    h.stamp = latest_.stamp;
    h.age = now - latest_.stamp;
    h.silence = now - arrival_;
    h.latency = arrival_ - latest_.stamp;
    h.stale = h.silence > settings_.max_gap || h.latency > settings_.max_latency;
    h.hand = latest_.hand.isometry();
    h.forearm = latest_.forearm.isometry();
    h.upper_arm = latest_.upper_arm.isometry();
  } else {
    h.stale = true;
    h.age = h.silence = h.latency = 0.0;
  }

  ObjectEstimate& o = est_.object;
  o.holder = holder;
  switch (holder) {
    case ObjectHolder::Person:
      o.valid = h.valid;
      o.stale = h.stale;
      // a tracked object is measured; otherwise it sits in the hand at the offset
      if (h.valid) o.pose = latest_.has_object ? latest_.object.isometry() : h.hand * settings_.hand_T_object;
      break;
    case ObjectHolder::Robot:
      o.valid = true;
      o.stale = false;
      o.pose = tcp_pose * tcp_T_object;
      break;
    case ObjectHolder::Nobody:
      o.valid = false;
      o.stale = true;
      break;
  }
  return est_;
}

}  // namespace handover::perception
