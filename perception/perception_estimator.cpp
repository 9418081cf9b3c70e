#include "perception/perception_estimator.hpp"

#include <algorithm>
#include <cmath>

namespace handover::perception {

namespace {
bool unitQuaternion(const Pose& p) { return std::abs(p.orientation.norm() - 1.0) <= 1e-3; }
bool validSample(const PoseSample& s) {
  return s.allFinite() && unitQuaternion(s.hand) && unitQuaternion(s.forearm) && unitQuaternion(s.upper_arm) &&
         (!s.has_object || unitQuaternion(s.object));
}
}  // namespace

PerceptionEstimator::PerceptionEstimator(const EstimatorSettings& settings)
    : settings_(settings),
      gate_(settings.gate),
      hand_f_(settings.filter),
      forearm_f_(settings.filter),
      upper_arm_f_(settings.filter),
      object_f_(settings.filter) {}

void PerceptionEstimator::reset() {
  have_ = false;
  est_ = PerceptionEstimate{};
  rejects_ = RejectCounts{};
  reseeds_ = 0;
  gate_.reset();
  hand_f_.clear();
  forearm_f_.clear();
  upper_arm_f_.clear();
  object_f_.clear();
}

bool PerceptionEstimator::addSample(const PoseSample& s, double arrival) {
  // checks of the value and the clock, then the gates on the motion
  RejectReason why = RejectReason::kCount;
  if (!validSample(s)) why = RejectReason::kInvalid;
  else if ((have_ && s.stamp < latest_.stamp) || s.stamp > arrival + settings_.max_gap) why = RejectReason::kTime;
  GateResult g;
  if (why == RejectReason::kCount) {
    BodyPrediction pred;
    if (settings_.model == MotionModel::kKalman && have_) {
      pred.valid = true;
      pred.hand = hand_f_.position(s.stamp);
      pred.forearm = forearm_f_.position(s.stamp);
      pred.upper_arm = upper_arm_f_.position(s.stamp);
      pred.has_object = object_f_.seeded() && latest_.has_object;
      if (pred.has_object) pred.object = object_f_.position(s.stamp);
    }
    g = gate_.check(s, pred);
    if (g.verdict == GateVerdict::kReject) why = g.reason;
  }
  if (why != RejectReason::kCount) {
    rejects_.add(why);
    return false;
  }

  const bool reseed = g.verdict == GateVerdict::kReseed;
  if (reseed) ++reseeds_;
  gate_.accept(s);
  if (settings_.model == MotionModel::kKalman) filter(s, reseed);
  else smooth(s);
  arrival_ = arrival;
  have_ = true;
  return true;
}

void PerceptionEstimator::filter(const PoseSample& s, bool reseed) {
  // a new track starts at rest where the sample is; a continuing one is corrected
  const auto feed = [&](PoseFilter& f, const Pose& z) {
    if (reseed || !f.seeded()) f.reset(z, s.stamp);
    else f.update(z, s.stamp);
  };
  feed(hand_f_, s.hand);
  feed(forearm_f_, s.forearm);
  feed(upper_arm_f_, s.upper_arm);
  if (settings_.smooth_rotations) smoothInto(smoothed_, s, have_ && !reseed);
  if (s.has_object) {
    if (!latest_.has_object || !have_) object_f_.clear();  // the object (re)appears in the stream
    feed(object_f_, s.object);
  }
  latest_ = s;
}

void PerceptionEstimator::smoothInto(PoseSample& latest_, const PoseSample& s, bool have) const {
  const double tau_rot = settings_.rotation_smoothing_time >= 0.0 ? settings_.rotation_smoothing_time
                                                                     : settings_.smoothing_time;
  if (have && (settings_.smoothing_time > 0.0 || tau_rot > 0.0)) {
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
  Eigen::Isometry3d tracked_object = Eigen::Isometry3d::Identity();
  if (have_) {
    h.stamp = latest_.stamp;
    h.age = now - latest_.stamp;
    h.silence = now - arrival_;
    h.latency = arrival_ - latest_.stamp;
    h.stale = h.silence > settings_.max_gap || h.latency > settings_.max_latency;
    if (settings_.model == MotionModel::kKalman) {
      // predicted forward by the sample's age, within the horizon
      h.predicted = std::clamp(h.age, 0.0, settings_.prediction_horizon);
      const double at = latest_.stamp + h.predicted;
      const double at_rot = latest_.stamp + std::clamp(h.age, 0.0, settings_.rotation_prediction_horizon);
      h.hand = hand_f_.predict(at, at_rot, settings_.prediction_significance).isometry();
      h.forearm = forearm_f_.predict(at, at_rot, settings_.prediction_significance).isometry();
      h.upper_arm = upper_arm_f_.predict(at, at_rot, settings_.prediction_significance).isometry();
      if (latest_.has_object) tracked_object = object_f_.predict(at, at_rot, settings_.prediction_significance).isometry();
      if (settings_.smooth_rotations) {
        h.hand.linear() = smoothed_.hand.orientation.toRotationMatrix();
        h.forearm.linear() = smoothed_.forearm.orientation.toRotationMatrix();
        h.upper_arm.linear() = smoothed_.upper_arm.orientation.toRotationMatrix();
        if (latest_.has_object && smoothed_.has_object) tracked_object.linear() = smoothed_.object.orientation.toRotationMatrix();
      }
      h.has_velocity = true;
      h.hand_velocity << hand_f_.velocity(), hand_f_.angularVelocity();
      h.hand_speed_std = std::sqrt(std::max(0.0, hand_f_.positionCovariance().vv));
    } else {
      h.has_velocity = false;
      h.hand_speed_std = 0.0;
      h.predicted = 0.0;
      h.hand = latest_.hand.isometry();
      h.forearm = latest_.forearm.isometry();
      h.upper_arm = latest_.upper_arm.isometry();
      if (latest_.has_object) tracked_object = latest_.object.isometry();
    }
  } else {
    h.stale = true;
    h.has_velocity = false;
    h.hand_speed_std = 0.0;
    h.age = h.silence = h.latency = h.predicted = 0.0;
  }

  ObjectEstimate& o = est_.object;
  o.holder = holder;
  switch (holder) {
    case ObjectHolder::Person:
      o.valid = h.valid;
      o.stale = h.stale;
      // a tracked object is measured; otherwise it sits in the hand at the offset
      if (h.valid) o.pose = latest_.has_object ? tracked_object : h.hand * settings_.hand_T_object;
      o.has_velocity = h.valid && h.has_velocity;
      o.speed_std = o.has_velocity ? h.hand_speed_std : 0.0;
      if (o.has_velocity && latest_.has_object) {
        o.velocity << object_f_.velocity(), object_f_.angularVelocity();
        o.speed_std = std::sqrt(std::max(0.0, object_f_.positionCovariance().vv));
      } else if (o.has_velocity) {  // carried rigidly by the hand
        const Eigen::Vector3d w = h.hand_velocity.tail<3>();
        const Eigen::Vector3d lever = o.pose.translation() - h.hand.translation();
        o.velocity.head<3>() = h.hand_velocity.head<3>() + w.cross(lever);
        o.velocity.tail<3>() = w;
        // the turn's uncertainty at the lever arm is the object's too: a young track of a hand at
        // rest under 2 deg of noise read 0.5 m/s at an object 9 cm from it, "known" to 0.18 m/s, and
        // an approach began toward a person who had not moved yet (g1013_00845). (A velocity is the
        // Kalman model's: h.has_velocity)
        o.speed_std = std::sqrt(std::max(0.0, hand_f_.positionCovariance().vv) +
                                std::max(0.0, hand_f_.rotationCovariance().vv) * lever.squaredNorm());
      }
      break;
    case ObjectHolder::Robot:
      o.valid = true;
      o.stale = false;
      o.has_velocity = false;
      o.speed_std = 0.0;
      o.pose = tcp_pose * tcp_T_object;
      break;
    case ObjectHolder::Nobody:
      o.valid = false;
      o.stale = true;
      o.has_velocity = false;
      o.speed_std = 0.0;
      break;
  }
  return est_;
}

}  // namespace handover::perception
