#include "perception/perception_estimator.hpp"

namespace handover::perception {

PerceptionEstimator::PerceptionEstimator(const EstimatorSettings& settings) : settings_(settings) {}

void PerceptionEstimator::reset() {
  have_ = false;
  est_ = PerceptionEstimate{};
  rejected_ = 0;
}

bool PerceptionEstimator::addSample(const PoseSample& s) {
  if (!s.allFinite() || (have_ && s.stamp < latest_.stamp)) {
    ++rejected_;
    return false;
  }
  latest_ = s;
  have_ = true;
  return true;
}

int PerceptionEstimator::update(double now, PoseSource& source) {
  int n = 0;
  PoseSample s;
  while (source.poll(now, s)) n += addSample(s) ? 1 : 0;
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
    h.stale = h.age > settings_.max_age;
    h.hand = latest_.hand.isometry();
    h.forearm = latest_.forearm.isometry();
    h.upper_arm = latest_.upper_arm.isometry();
  } else {
    h.stale = true;
    h.age = 0.0;
  }

  ObjectEstimate& o = est_.object;
  o.holder = holder;
  switch (holder) {
    case ObjectHolder::Person:
      o.valid = h.valid;
      o.stale = h.stale;
      if (h.valid) o.pose = h.hand * settings_.hand_T_object;
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
