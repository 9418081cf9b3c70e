#include "perception/pose_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace handover::perception;

namespace {
Pose poseAt(double t, const Eigen::Vector3d& p0, const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
  Pose p;
  p.position = p0 + v * t;
  const double a = w.norm() * t;
  p.orientation = a > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(a, w.normalized())) : Eigen::Quaterniond::Identity();
  return p;
}
}  // namespace

TEST(PoseFilter, ConstantVelocityAndTurnRateArePredictedExactly) {
  PoseFilter f;
  const Eigen::Vector3d p0(0.5, 0.1, 0.3), v(-0.8, 0.3, 0.2), w(0.3, -0.5, 1.2);
  for (int k = 0; k <= 120; ++k) f.update(poseAt(k / 60.0, p0, v, w), k / 60.0);
  EXPECT_LT((f.velocity() - v).norm(), 1e-3);
  EXPECT_LT((f.angularVelocity() - w).norm(), 1e-3);
  // 0.2 s ahead of the last sample
  const Pose truth = poseAt(2.2, p0, v, w), guess = f.predict(2.2);
  EXPECT_LT((guess.position - truth.position).norm(), 1e-3);
  EXPECT_LT(truth.orientation.angularDistance(guess.orientation), 1e-3);
  // rotation held at the sample's time, position predicted
  const Pose split = f.predict(2.2, 2.0);
  EXPECT_LT((split.position - truth.position).norm(), 1e-3);
  EXPECT_LT(poseAt(2.0, p0, v, w).orientation.angularDistance(split.orientation), 1e-3);
}

TEST(PoseFilter, FiltersNoiseOfAPoseAtRest) {
  PoseFilterSettings s;
  s.position_noise = 0.005;
  s.rotation_noise = 0.05;
  PoseFilter f(s);
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  double e_raw = 0, e_est = 0, r_raw = 0, r_est = 0;
  int count = 0;
  for (int k = 0; k < 600; ++k) {
    Pose z;
    z.position = Eigen::Vector3d(0.5, 0, 0.3) + 0.005 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    const Eigen::Vector3d dr = 0.05 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    z.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(dr.norm(), dr.normalized()));
    f.update(z, k / 60.0);
    if (k < 60) continue;
    const Pose est = f.predict(k / 60.0);
    e_raw += (z.position - Eigen::Vector3d(0.5, 0, 0.3)).squaredNorm();
    e_est += (est.position - Eigen::Vector3d(0.5, 0, 0.3)).squaredNorm();
    r_raw += dr.squaredNorm();
    const double a = est.orientation.angularDistance(Eigen::Quaterniond::Identity());
    r_est += a * a;
    ++count;
  }
  // several times less variance than the measurements
  EXPECT_LT(e_est, 0.3 * e_raw);
  EXPECT_LT(r_est, 0.3 * r_raw);
}

TEST(PoseFilter, ResetStartsATrackAtRestWhereTheSampleIs) {
  PoseFilter f;
  EXPECT_FALSE(f.seeded());
  f.update(poseAt(0.0, {0.4, 0, 0.2}, {1, 0, 0}, {0, 0, 1}), 1.0);
  EXPECT_TRUE(f.seeded());
  EXPECT_EQ(f.velocity(), Eigen::Vector3d::Zero());
  EXPECT_LT((f.predict(1.5).position - Eigen::Vector3d(0.4, 0, 0.2)).norm(), 1e-12);
  // the velocity's uncertainty starts large: the first steps follow the data
  EXPECT_GT(f.positionCovariance().vv, 0.5);
}

TEST(PoseFilter, EstimatesTheSensorsNoiseAndSmoothsANoisyOneMore) {
  // a sensor noisier than the configured floor: 1 cm and 5 deg
  PoseFilterSettings s;
  PoseFilter adaptive(s);
  s.noise_adaptation_time = 0.0;
  PoseFilter fixed(s);
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  double e_adaptive = 0, e_fixed = 0, r_adaptive = 0, r_fixed = 0;
  for (int k = 0; k < 600; ++k) {
    Pose z;
    z.position = Eigen::Vector3d(0.5, 0, 0.3) + 0.01 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    const Eigen::Vector3d dr = (5.0 * M_PI / 180.0) * Eigen::Vector3d(n(rng), n(rng), n(rng));
    z.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(dr.norm(), dr.normalized()));
    adaptive.update(z, k / 60.0);
    fixed.update(z, k / 60.0);
    if (k < 120) continue;
    // the velocity (what decides whether the person comes or goes) and the rotation
    e_adaptive += adaptive.velocity().squaredNorm();
    e_fixed += fixed.velocity().squaredNorm();
    r_adaptive += std::pow(adaptive.predict(k / 60.0).orientation.angularDistance(Eigen::Quaterniond::Identity()), 2);
    r_fixed += std::pow(fixed.predict(k / 60.0).orientation.angularDistance(Eigen::Quaterniond::Identity()), 2);
  }
  EXPECT_NEAR(adaptive.positionNoise(), 0.01, 0.002);
  EXPECT_NEAR(adaptive.rotationNoise(), 5.0 * M_PI / 180.0, 0.01);
  EXPECT_DOUBLE_EQ(fixed.positionNoise(), s.position_noise);
  EXPECT_LT(e_adaptive, 0.5 * e_fixed);
  EXPECT_LT(r_adaptive, 0.7 * r_fixed);
}

TEST(PoseFilter, ASignificancePredictionIgnoresTheVelocityNoiseOfABodyAtRest) {
  PoseFilter f;
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  double plain = 0, significant = 0;
  for (int k = 0; k < 600; ++k) {
    Pose z;
    z.position = Eigen::Vector3d(0.5, 0, 0.3) + 0.004 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    f.update(z, k / 60.0);
    if (k < 120) continue;
    // 0.1 s ahead, as with a 0.1 s latency
    plain += (f.predict(k / 60.0 + 0.1, k / 60.0, 0.0).position - Eigen::Vector3d(0.5, 0, 0.3)).squaredNorm();
    significant += (f.predict(k / 60.0 + 0.1, k / 60.0, 2.0).position - Eigen::Vector3d(0.5, 0, 0.3)).squaredNorm();
  }
  EXPECT_LT(significant, 0.7 * plain);
  // a body that clearly moves is predicted (almost) in full
  PoseFilter g;
  for (int k = 0; k <= 60; ++k) g.update(poseAt(k / 60.0, {0.3, 0, 0.3}, {0.8, 0, 0}, {0, 0, 0}), k / 60.0);
  EXPECT_NEAR(g.predict(1.2, 1.0, 2.0).position.x(), 0.3 + 0.8 * 1.2, 0.01);
}
