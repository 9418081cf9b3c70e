#include "perception/observation_target.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace handover::perception;

namespace {

constexpr double kDt = 0.001;
constexpr double kK = 1500.0;
const double kD = 2.0 * std::sqrt(kK);

// the observation task's PD reference model, integrated at 1 ms
struct Observed {
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d w = Eigen::Vector3d::Zero(), alpha = Eigen::Vector3d::Zero();
  void step(const Eigen::Isometry3d& target) {
    a = kK * (target.translation() - p) - kD * v;
    const Eigen::AngleAxisd err(target.rotation() * R.transpose());
    alpha = kK * err.angle() * err.axis() - kD * w;
    v += a * kDt;
    p += v * kDt;
    w += alpha * kDt;
    const double n = w.norm() * kDt;
    if (n > 0) R = Eigen::AngleAxisd(n, w.normalized()).toRotationMatrix() * R;
  }
};

PerceptionEstimate scene(const Eigen::Isometry3d& hand, const Eigen::Isometry3d& object, bool hand_fresh = true) {
  PerceptionEstimate e;
  e.human.valid = true;
  e.human.stale = !hand_fresh;
  e.human.hand = hand;
  e.object.valid = true;
  e.object.stale = false;
  e.object.holder = ObjectHolder::Robot;
  e.object.pose = object;
  return e;
}

struct Peaks {
  double acc = 0.0, ang_acc = 0.0, step = 0.0;
  Observed final_state;
};

// tracks the object, switches to the hand at t = 1 s, runs until 3 s
Peaks runSwitch(double blend_time, const Eigen::Isometry3d& hand, const Eigen::Isometry3d& object) {
  ObservationTarget target({blend_time});
  Observed obs;
  obs.p = object.translation();
  obs.R = object.rotation();
  target.select(TargetSource::Object, 0.0);
  Peaks pk;
  const auto est = scene(hand, object);
  for (int k = 0; k <= 3000; ++k) {
    const double t = k * kDt;
    if (k == 1000) target.select(TargetSource::Hand, t);
    const Eigen::Vector3d before = obs.p;
    obs.step(target.update(t, est).pose);
    pk.acc = std::max(pk.acc, obs.a.norm());
    pk.ang_acc = std::max(pk.ang_acc, obs.alpha.norm());
    pk.step = std::max(pk.step, (obs.p - before).norm());
  }
  pk.final_state = obs;
  return pk;
}

}  // namespace

TEST(ObservationTarget, SwitchBlendsWithoutJumpAndBoundedAcceleration) {
  Eigen::Isometry3d object = Eigen::Isometry3d::Identity(), hand = Eigen::Isometry3d::Identity();
  object.translation() = Eigen::Vector3d(0.55, 0.05, 0.35);
  hand.translation() = Eigen::Vector3d(0.60, 0.12, 0.28);
  hand.linear() = Eigen::AngleAxisd(0.6, Eigen::Vector3d(0, 0, 1)).toRotationMatrix();
  const double dist = (hand.translation() - object.translation()).norm();
  const double T = 0.5;
  const Peaks blended = runSwitch(T, hand, object);
  // a critically damped reference model never exceeds its reference's peak
  // acceleration; minimum jerk peaks at 5.7735 D / T^2
  EXPECT_LT(blended.acc, 1.05 * 5.7735 * dist / (T * T));
  EXPECT_LT(blended.ang_acc, 1.05 * 5.7735 * 0.6 / (T * T));
  EXPECT_LT(blended.step, 1.05 * 1.875 * dist / T * kDt);  // no position jump
  EXPECT_NEAR((blended.final_state.p - hand.translation()).norm(), 0.0, 1e-4);
  EXPECT_LT(Eigen::AngleAxisd(blended.final_state.R.transpose() * hand.rotation()).angle(), 1e-3);

  // the same switch without blending kicks the model with K * D
  const Peaks hard = runSwitch(0.0, hand, object);
  EXPECT_GT(hard.acc, 0.9 * kK * dist);
  EXPECT_GT(hard.acc, 10 * blended.acc);
}

TEST(ObservationTarget, AttachedFrameAndPhase) {
  Eigen::Isometry3d object = Eigen::Isometry3d::Identity(), hand = Eigen::Isometry3d::Identity();
  object.translation() = Eigen::Vector3d(0.5, 0, 0.3);
  hand.translation() = Eigen::Vector3d(0.6, 0, 0.3);
  Eigen::Isometry3d grasp = Eigen::Isometry3d::Identity();
  grasp.translation() = Eigen::Vector3d(0, 0, 0.05);
  ObservationTarget target({0.4});
  target.select(TargetSource::Object, 0.0, grasp);
  const auto est = scene(hand, object);
  EXPECT_TRUE(target.update(0.0, est).pose.isApprox(object * grasp));
  target.select(TargetSource::Object, 0.1, grasp);  // same selection: no blend
  EXPECT_FALSE(target.update(0.1, est).blending);
  target.select(TargetSource::Hand, 1.0);
  const auto& mid = target.update(1.2, est);
  EXPECT_TRUE(mid.blending);
  EXPECT_NEAR(mid.blend_phase, 0.5, 1e-12);
  EXPECT_TRUE(mid.pose.translation().isApprox(0.5 * ((object * grasp).translation() + hand.translation())));
  const auto& done = target.update(1.41, est);
  EXPECT_FALSE(done.blending);
  EXPECT_TRUE(done.pose.isApprox(hand));
}

TEST(ObservationTarget, StaleSourceHoldsLastTarget) {
  Eigen::Isometry3d object = Eigen::Isometry3d::Identity(), hand = Eigen::Isometry3d::Identity();
  hand.translation() = Eigen::Vector3d(0.6, 0, 0.3);
  ObservationTarget target({0.3});
  target.select(TargetSource::Hand, 0.0);
  EXPECT_TRUE(target.update(0.0, scene(hand, object)).valid);
  Eigen::Isometry3d moved = hand;
  moved.translation().x() = 0.9;
  const auto& out = target.update(0.5, scene(moved, object, /*hand_fresh=*/false));
  EXPECT_FALSE(out.valid);
  EXPECT_TRUE(out.pose.isApprox(hand));
}
