#include "perception/simulated_pose_sensor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace handover;
using namespace handover::perception;

namespace {

io::HumanBodyPoses bodiesAt(const Eigen::Vector3d& hand, double yaw = 0.3) {
  io::HumanBodyPoses b;
  b.hand.translation() = hand;
  b.hand.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  b.forearm.translation() = hand + Eigen::Vector3d(0.25, 0, 0);
  b.upper_arm.translation() = hand + Eigen::Vector3d(0.5, 0, 0.2);
  return b;
}

// runs the sensor at 1 kHz for `seconds` on a static pose; returns delivered samples
std::vector<PoseSample> runStatic(SimulatedPoseSensor& s, double seconds, const io::HumanBodyPoses& b) {
  std::vector<PoseSample> out;
  const long n = std::lround(seconds * 1000);
  for (long k = 0; k <= n; ++k) {
    const double t = k * 0.001;
    s.observe(t, b);
    PoseSample p;
    while (s.poll(t, p)) out.push_back(p);
  }
  return out;
}

Eigen::Vector3d rotationError(const Pose& measured, const Eigen::Isometry3d& truth) {
  const Eigen::AngleAxisd aa(truth.rotation().transpose() * measured.orientation.toRotationMatrix());
  return aa.angle() * aa.axis();
}

}  // namespace

TEST(SimulatedPoseSensor, RateOverTenSeconds) {
  SensorSettings cfg;
  cfg.rate_hz = 60.0;
  SimulatedPoseSensor s(cfg, 1);
  const auto samples = runStatic(s, 10.0, bodiesAt({0.5, 0, 0.3}));
  // samples at 0, 1/60, ..., 10 s
  EXPECT_GE(samples.size(), 600u);
  EXPECT_LE(samples.size(), 601u);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    EXPECT_NEAR(samples[i].stamp - samples[i - 1].stamp, 1.0 / 60.0, 0.0011);
  }
}

TEST(SimulatedPoseSensor, LatencyDelaysDelivery) {
  SensorSettings cfg;
  cfg.rate_hz = 100.0;
  cfg.latency = 0.05;
  SimulatedPoseSensor s(cfg, 2);
  const double speed = 0.2;  // m/s along x
  int n = 0;
  for (int k = 0; k <= 3000; ++k) {
    const double t = k * 0.001;
    s.observe(t, bodiesAt({speed * t, 0, 0.3}));
    PoseSample p;
    while (s.poll(t, p)) {
      ++n;
      // the measured value is the truth of `latency` ago (at the stamp)
      const double lag = (speed * t - p.hand.position.x()) / speed;
      EXPECT_NEAR(lag, cfg.latency, 0.0011);
      EXPECT_NEAR(p.hand.position.x(), speed * p.stamp, 1e-12);
      EXPECT_GE(t + 1e-9, p.stamp + cfg.latency);
    }
  }
  EXPECT_GT(n, 290);
}

TEST(SimulatedPoseSensor, NoiseLevelMatchesSettings) {
  SensorSettings cfg;
  cfg.rate_hz = 1000.0;
  cfg.noise_pos = 0.004;
  cfg.noise_rot_deg = 2.0;
  SimulatedPoseSensor s(cfg, 3);
  const auto truth = bodiesAt({0.5, 0.1, 0.3});
  const auto samples = runStatic(s, 20.0, truth);
  ASSERT_GT(samples.size(), 19000u);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sq = Eigen::Vector3d::Zero();
  Eigen::Vector3d rsum = Eigen::Vector3d::Zero(), rsq = Eigen::Vector3d::Zero();
  for (const auto& p : samples) {
    const Eigen::Vector3d e = p.hand.position - truth.hand.translation();
    const Eigen::Vector3d r = rotationError(p.hand, truth.hand);
    sum += e;
    sq += e.cwiseProduct(e);
    rsum += r;
    rsq += r.cwiseProduct(r);
  }
  const double n = static_cast<double>(samples.size());
  const double rot_std = 2.0 * M_PI / 180.0;
  for (int i = 0; i < 3; ++i) {
    const double sd = std::sqrt(sq[i] / n - std::pow(sum[i] / n, 2));
    EXPECT_NEAR(sd, cfg.noise_pos, 0.1 * cfg.noise_pos) << "axis " << i;
    const double rsd = std::sqrt(rsq[i] / n - std::pow(rsum[i] / n, 2));
    EXPECT_NEAR(rsd, rot_std, 0.1 * rot_std) << "axis " << i;
  }
  // the forearm is noisy too
  EXPECT_GT((samples[5].forearm.position - truth.forearm.translation()).norm(), 0.0);
}

TEST(SimulatedPoseSensor, NoSamplesInsideDropouts) {
  SensorSettings cfg;
  cfg.rate_hz = 60.0;
  cfg.dropouts = {{1.0, 1.5}, {3.0, 3.2}};
  SimulatedPoseSensor s(cfg, 4);
  const auto samples = runStatic(s, 5.0, bodiesAt({0.5, 0, 0.3}));
  int before = 0, between = 0, after = 0;
  for (const auto& p : samples) {
    EXPECT_FALSE(p.stamp >= 1.0 && p.stamp < 1.5) << p.stamp;
    EXPECT_FALSE(p.stamp >= 3.0 && p.stamp < 3.2) << p.stamp;
    before += p.stamp < 1.0;
    between += p.stamp >= 1.5 && p.stamp < 3.0;
    after += p.stamp >= 3.2;
  }
  EXPECT_GT(before, 55);
  EXPECT_GT(between, 85);
  EXPECT_GT(after, 100);
  EXPECT_NEAR(static_cast<double>(samples.size()), 60 * (5.0 - 0.7), 2.0);
}

TEST(SimulatedPoseSensor, ConstantOffsetIsTheMeanError) {
  SensorSettings cfg;
  cfg.rate_hz = 500.0;
  cfg.noise_pos = 0.002;
  cfg.noise_rot_deg = 0.5;
  cfg.offset.translation() = Eigen::Vector3d(0.01, -0.02, 0.015);
  cfg.offset.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  SimulatedPoseSensor s(cfg, 5);
  const auto truth = bodiesAt({0.5, 0.1, 0.3});
  const auto samples = runStatic(s, 10.0, truth);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), rmean = Eigen::Vector3d::Zero();
  for (const auto& p : samples) {
    mean += p.hand.position - truth.hand.translation();
    rmean += rotationError(p.hand, truth.hand);
  }
  mean /= static_cast<double>(samples.size());
  rmean /= static_cast<double>(samples.size());
  // 5 standard errors of the mean
  const double tol = 5 * cfg.noise_pos / std::sqrt(static_cast<double>(samples.size()));
  EXPECT_NEAR(mean.x(), 0.01, tol);
  EXPECT_NEAR(mean.y(), -0.02, tol);
  EXPECT_NEAR(mean.z(), 0.015, tol);
  EXPECT_NEAR(rmean.z(), 0.1, 5e-3);
  EXPECT_NEAR(rmean.x(), 0.0, 5e-3);
}

TEST(SimulatedPoseSensor, SeedMakesItRepeatable) {
  SensorSettings cfg;
  cfg.noise_pos = 0.003;
  SimulatedPoseSensor a(cfg, 42), b(cfg, 42), c(cfg, 43);
  const auto truth = bodiesAt({0.5, 0, 0.3});
  const auto sa = runStatic(a, 1.0, truth), sb = runStatic(b, 1.0, truth), sc = runStatic(c, 1.0, truth);
  ASSERT_EQ(sa.size(), sb.size());
  for (std::size_t i = 0; i < sa.size(); ++i) EXPECT_EQ(sa[i].hand.position, sb[i].hand.position);
  EXPECT_NE(sa[3].hand.position, sc[3].hand.position);
}
