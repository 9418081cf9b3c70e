#include "perception/perception_estimator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "perception/csv_pose_source.hpp"

using namespace handover::perception;

namespace {
PoseSample at(double t, double x) {
  PoseSample s;
  s.stamp = t;
  s.hand.position = {x, 0.0, 0.3};
  s.hand.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  return s;
}
}  // namespace

TEST(PerceptionEstimator, SmoothingIsStaleAfterMaxGapAndNeverExtrapolates) {
  EstimatorSettings cfg;
  cfg.model = MotionModel::kSmoothing;
  cfg.max_gap = 0.1;
  PerceptionEstimator est(cfg);
  EXPECT_FALSE(est.estimate(0.0, ObjectHolder::Person).human.valid);
  EXPECT_TRUE(est.estimate(0.0, ObjectHolder::Person).human.stale);
  ASSERT_TRUE(est.addSample(at(1.0, 0.50)));
  ASSERT_TRUE(est.addSample(at(1.02, 0.52)));  // moving at 1 m/s
  const auto& fresh = est.estimate(1.05, ObjectHolder::Person);
  EXPECT_TRUE(fresh.human.valid);
  EXPECT_FALSE(fresh.human.stale);
  EXPECT_NEAR(fresh.human.age, 0.03, 1e-12);
  const auto& old = est.estimate(1.2, ObjectHolder::Person);
  EXPECT_TRUE(old.human.stale);
  EXPECT_TRUE(old.object.stale);
  // the last sample, not a guess of where the hand went
  EXPECT_DOUBLE_EQ(old.human.hand.translation().x(), 0.52);
}

TEST(PerceptionEstimator, RejectsOutOfOrderAndNonFinite) {
  PerceptionEstimator est;
  EXPECT_TRUE(est.addSample(at(1.0, 0.5)));
  EXPECT_FALSE(est.addSample(at(0.9, 0.6)));
  PoseSample bad = at(1.1, std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE(est.addSample(bad));
  EXPECT_EQ(est.rejected(), 2);
  EXPECT_DOUBLE_EQ(est.estimate(1.1, ObjectHolder::Person).human.hand.translation().x(), 0.5);
}

TEST(PerceptionEstimator, ObjectPoseFromWhoeverHoldsIt) {
  EstimatorSettings cfg;
  cfg.hand_T_object.translation() = Eigen::Vector3d(0, 0, 0.04);
  PerceptionEstimator est(cfg);
  // drains a source
  CsvPoseSource src({at(0.5, 0.4), at(1.0, 0.5), at(2.0, 0.9)}, 0.0);
  EXPECT_EQ(est.update(1.0, src), 2);
  const auto& e = est.estimate(1.0, ObjectHolder::Person);
  ASSERT_TRUE(e.object.valid);
  const Eigen::Isometry3d expected = at(1.0, 0.5).hand.isometry() * cfg.hand_T_object;
  EXPECT_TRUE(e.object.pose.isApprox(expected, 1e-12));

  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
  tcp.translation() = Eigen::Vector3d(0.3, 0.1, 0.45);
  tcp.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  Eigen::Isometry3d grasp = Eigen::Isometry3d::Identity();
  grasp.translation() = Eigen::Vector3d(0, 0, 0.02);
  // robot holds: forward kinematics, fresh even with stale hand data
  const auto& r = est.estimate(10.0, ObjectHolder::Robot, tcp, grasp);
  EXPECT_TRUE(r.human.stale);
  EXPECT_TRUE(r.object.valid);
  EXPECT_FALSE(r.object.stale);
  EXPECT_TRUE(r.object.pose.isApprox(tcp * grasp, 1e-12));
  EXPECT_FALSE(est.estimate(1.0, ObjectHolder::Nobody).object.valid);
}

TEST(PerceptionEstimator, TrackedObjectPoseReplacesTheHandOffset) {
  EstimatorSettings cfg;
  cfg.hand_T_object.translation() = Eigen::Vector3d(0.0, 0.0, 0.05);
  cfg.model = MotionModel::kSmoothing;
  cfg.smoothing_time = 0.03;
  PerceptionEstimator est(cfg);
  PoseSample s = at(1.0, 0.5);
  s.has_object = true;
  s.object.position = {0.7, 0.1, 0.35};  // away from hand * offset
  s.object.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX()));
  ASSERT_TRUE(est.addSample(s));
  EXPECT_TRUE(est.objectTracked());
  const auto& e = est.estimate(1.0, ObjectHolder::Person);
  EXPECT_LT((e.object.pose.translation() - s.object.position).norm(), 1e-12);
  EXPECT_LT((e.object.pose.linear() - s.object.orientation.toRotationMatrix()).norm(), 1e-12);
  // a later sample moves the tracked object; smoothing applies to it like to the hand
  PoseSample s2 = s;
  s2.stamp = 1.01;
  s2.object.position.x() = 0.8;
  ASSERT_TRUE(est.addSample(s2));
  const double x = est.estimate(1.01, ObjectHolder::Person).object.pose.translation().x();
  EXPECT_GT(x, 0.7);
  EXPECT_LT(x, 0.8);
  // without the object in the sample, the hand offset is back
  PoseSample s3 = at(1.02, 0.5);
  ASSERT_TRUE(est.addSample(s3));
  EXPECT_FALSE(est.objectTracked());
  const auto& e3 = est.estimate(1.02, ObjectHolder::Person);
  EXPECT_LT((e3.object.pose.translation() - e3.human.hand * Eigen::Vector3d(0, 0, 0.05)).norm(), 1e-12);
  // the robot's forward kinematics win once the robot holds it
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
  tcp.translation() = Eigen::Vector3d(0.4, 0.0, 0.5);
  EXPECT_LT((est.estimate(1.02, ObjectHolder::Robot, tcp).object.pose.translation() - tcp.translation()).norm(), 1e-12);
}

TEST(PerceptionEstimator, SteadyLatencyIsNotStalenessButLateSamplesAre) {
  EstimatorSettings cfg;
  cfg.max_gap = 0.1;
  cfg.max_latency = 0.2;
  PerceptionEstimator est(cfg);
  // a 60 Hz stream 90 ms late: every sample is ~0.1 s old when read, yet the
  // stream is alive
  const double period = 1.0 / 60, latency = 0.09;
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(est.addSample(at(1.0 + k * period, 0.5 + 0.01 * k), 1.0 + k * period + latency));
  const double last_arrival = 1.0 + 2 * period + latency;
  const auto& e = est.estimate(last_arrival + 0.015, ObjectHolder::Person);
  EXPECT_GT(e.human.age, 0.1);
  EXPECT_NEAR(e.human.silence, 0.015, 1e-9);
  EXPECT_NEAR(e.human.latency, latency, 1e-9);
  EXPECT_FALSE(e.human.stale);
  EXPECT_FALSE(e.object.stale);
  // the stream stops: stale once no sample has come for max_gap
  EXPECT_TRUE(est.estimate(last_arrival + 0.11, ObjectHolder::Person).human.stale);

  // samples that arrive 0.3 s late are too late to act on, however steady
  PerceptionEstimator est2(cfg);
  ASSERT_TRUE(est2.addSample(at(1.0, 0.5), 1.3));
  ASSERT_TRUE(est2.addSample(at(1.0 + period, 0.51), 1.3 + period));
  const auto& e2 = est2.estimate(1.3 + period, ObjectHolder::Person);
  EXPECT_TRUE(e2.human.valid);
  EXPECT_TRUE(e2.human.stale);
}

// issue 16: a sensor 0.2 s late made the robot follow where the hand was
// 0.2 s ago (a hand at 1 m/s: 0.2 m behind); the estimate is now predicted
// forward by the sample's age
TEST(PerceptionEstimator, LatencyIsCompensatedByPrediction) {
  EstimatorSettings cfg;  // the Kalman filter, predicted up to prediction_horizon
  PerceptionEstimator est(cfg);
  const double period = 1.0 / 60, latency = 0.2, speed = 1.0;
  double worst = 0.0;
  for (int k = 0; k < 90; ++k) {
    const double stamp = 1.0 + k * period, now = stamp + latency;
    ASSERT_TRUE(est.addSample(at(stamp, 0.3 + speed * (stamp - 1.0)), now));
    const auto& e = est.estimate(now, ObjectHolder::Person);
    EXPECT_FALSE(e.human.stale);
    if (k >= 45) worst = std::max(worst, std::abs(e.human.hand.translation().x() - (0.3 + speed * (now - 1.0))));
  }
  EXPECT_LT(worst, 0.01);
  // and between samples, the estimate moves on with the hand
  const double last = 1.0 + 89 * period + latency;
  const double x0 = est.estimate(last, ObjectHolder::Person).human.hand.translation().x();
  const double x1 = est.estimate(last + 0.01, ObjectHolder::Person).human.hand.translation().x();
  EXPECT_NEAR(x1 - x0, 0.01, 1e-3);
}

// issue 16: a latency above max_latency (0.1 s, while the scenario contract
// allows 1 s) made every sample stale and the robot never moved
TEST(PerceptionEstimator, ALatencyTheContractAllowsIsNotStale) {
  PerceptionEstimator est;  // product defaults
  const double period = 1.0 / 60, latency = 0.9;
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(est.addSample(at(k * period, 0.5), k * period + latency));
  EXPECT_FALSE(est.estimate(9 * period + latency, ObjectHolder::Person).human.stale);
}

// the Kalman filter's rotation made a presented object jitter in the hand
// (give, noisy sensing: the arm never settled in Present); rotations are
// smoothed first-order as before, positions filtered and predicted
TEST(PerceptionEstimator, KalmanPositionsWithSmoothedRotations) {
  EstimatorSettings cfg;
  cfg.rotation_smoothing_time = 0.1;
  ASSERT_TRUE(cfg.smooth_rotations);
  PerceptionEstimator est(cfg);
  PoseSample a = at(1.0, 0.5), b = at(1.0 + 1.0 / 60, 0.5);
  b.hand.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()));  // +0.1 rad
  ASSERT_TRUE(est.addSample(a));
  ASSERT_TRUE(est.addSample(b));
  const double w = 1.0 - std::exp(-(1.0 / 60) / 0.1);
  const Eigen::AngleAxisd got(est.estimate(b.stamp, ObjectHolder::Person).human.hand.linear());
  EXPECT_NEAR(got.angle(), 0.3 + w * 0.1, 1e-6);
}

// An object carried in the hand moves with the hand's turn at the lever arm,
// so the uncertainty of that turn is the object's too. A young track of a
// hand at rest under 2 deg of rotation noise read 0.5 m/s at an object 9 cm
// from it, reported as known to 0.18 m/s (the hand's own linear figure), and
// an approach began toward a person who had not moved (g1013_00845). Here an
// object 25 cm from the grip point (a tube held by one end).
TEST(PerceptionEstimator, AnObjectInTheHandIsAsUncertainAsTheHandsTurnAtItsDistance) {
  EstimatorSettings near_cfg, far_cfg;
  far_cfg.hand_T_object.translation() = Eigen::Vector3d(0.0, 0.0, 0.25);
  PerceptionEstimator near_est(near_cfg), far_est(far_cfg);
  int within = 0, samples = 0;
  for (int k = 0; k < 12; ++k) {  // a hand at rest, its orientation flickering +-2 deg about x
    PoseSample s = at(1.0 + k / 90.0, 0.5);
    s.hand.orientation = s.hand.orientation * Eigen::Quaterniond(Eigen::AngleAxisd((k % 2 ? 1 : -1) * 0.035,
                                                                                   Eigen::Vector3d::UnitX()));
    ASSERT_TRUE(near_est.addSample(s));
    ASSERT_TRUE(far_est.addSample(s));
    const ObjectEstimate at_hand = near_est.estimate(s.stamp, ObjectHolder::Person).object;
    const PerceptionEstimate e = far_est.estimate(s.stamp, ObjectHolder::Person);
    ASSERT_TRUE(e.object.has_velocity);
    // at the hand's own origin nothing changes
    EXPECT_NEAR(at_hand.speed_std, e.human.hand_speed_std, 1e-12);
    if (k < 1) continue;
    ++samples;
    // the turn moves the object (omega x lever), and its uncertainty says so
    const double speed = e.object.velocity.head<3>().norm();
    if (speed <= 2.0 * e.object.speed_std) ++within;
  }
  EXPECT_EQ(within, samples) << "the flicker's speed at the object lies within two standard deviations";
}
