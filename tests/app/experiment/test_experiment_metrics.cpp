// The experiment's metrics on synthetic traces whose answers are known by construction.
#include <gtest/gtest.h>

#include <cmath>

#include "app/experiment/experiment_metrics.hpp"

namespace handover::app {
namespace {

TEST(SettlingTime, FindsTheStartOfTheFinalStretchWithinTolerance) {
  // error |1 - t/2| on [0, 2] with a spike at t = 1.5
  std::vector<double> t, e;
  for (int i = 0; i <= 200; ++i) {
    t.push_back(i * 0.01);
    e.push_back(std::abs(1.0 - t.back() / 2.0));
  }
  e[150] = 0.5;  // above 0.2 at t = 1.5
  // e <= 0.2 holds from t = 1.6 on (1 - 1.6 / 2 = 0.2), never before
  const auto ts = settlingTime(t, e, 0.2);
  ASSERT_TRUE(ts.has_value());
  EXPECT_NEAR(*ts, 1.6, 1e-9);
  // never within tolerance at the end -> empty
  e.back() = 1.0;
  EXPECT_FALSE(settlingTime(t, e, 0.2).has_value());
  EXPECT_THROW(settlingTime(t, std::vector<double>(3, 0.0), 0.2), std::invalid_argument);
}

TEST(ExperimentMetrics, KnownRestAndSettlingTimesOnASyntheticReach) {
  // the hand moves until t = 1 (speed 0.5 m/s) and rests; the TCP's distance
  // to the true grasp frame decays as 0.2 exp(-(t - 1)) after t = 1, so it is
  // within 1 cm from t = 1 + ln(20); the orientation error 30 exp(-2 (t - 1))
  // deg is within 5 deg from t = 1 + ln(6) / 2, i.e. earlier
  std::vector<ExperimentSample> trace;
  const double dt = 0.001;
  for (int i = 0; i <= 8000; ++i) {
    ExperimentSample s;
    s.time = i * dt;
    s.hand_speed = s.time < 1.0 ? 0.5 : 0.0;
    const double d = s.time < 1.0 ? 0.2 : 0.2 * std::exp(-(s.time - 1.0));
    const double a_deg = s.time < 1.0 ? 30.0 : 30.0 * std::exp(-2.0 * (s.time - 1.0));
    s.grasp_true = Eigen::Translation3d(0.5, 0.1, 0.3) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
    s.tcp = s.grasp_true * Eigen::Translation3d(d, 0.0, 0.0) *
            Eigen::AngleAxisd(a_deg * M_PI / 180.0, Eigen::Vector3d::UnitY());
    s.reference = s.grasp_true;
    s.object_true = s.grasp_true;
    s.object_measured = s.grasp_true * Eigen::Translation3d(0.0, 0.002, 0.0);
    s.measured_valid = true;
    s.observed = s.grasp_true;
    trace.push_back(s);
  }
  const ExperimentMetrics m = computeExperimentMetrics(trace);
  ASSERT_TRUE(m.hand_rest_time && m.reached_time && m.rest_to_reached);
  EXPECT_NEAR(*m.hand_rest_time, 1.0, 1e-9);
  EXPECT_NEAR(*m.position_settle_time, 1.0 + std::log(20.0), dt);
  EXPECT_NEAR(*m.orientation_settle_time, 1.0 + std::log(6.0) / 2.0, dt);
  EXPECT_NEAR(*m.reached_time, 1.0 + std::log(20.0), dt);
  EXPECT_NEAR(*m.rest_to_reached, std::log(20.0), dt);
  ASSERT_TRUE(m.orientation_first.has_value());
  EXPECT_TRUE(*m.orientation_first);
  EXPECT_NEAR(m.obs_pos_vs_true.max, 0.0, 1e-12);
  EXPECT_NEAR(m.obs_pos_vs_measured.rms, 0.002, 1e-9);
  EXPECT_NEAR(m.true_pos.max, 0.2, 1e-9);
  EXPECT_NEAR(m.final_pos_error, 0.2 * std::exp(-7.0), 1e-9);
  EXPECT_EQ(m.position_violations + m.velocity_violations + m.torque_violations, 0);
}

TEST(ExperimentMetrics, CountsViolationsAndRejectsAnEmptyTrace) {
  std::vector<ExperimentSample> trace(5);
  for (int i = 0; i < 5; ++i) trace[i].time = i * 0.001;
  trace[2].velocity_violation = true;
  trace[3].torque_violation = true;
  trace[4].torque_violation = true;
  const ExperimentMetrics m = computeExperimentMetrics(trace);
  EXPECT_EQ(m.position_violations, 0);
  EXPECT_EQ(m.velocity_violations, 1);
  EXPECT_EQ(m.torque_violations, 2);
  EXPECT_THROW(computeExperimentMetrics({}), std::invalid_argument);
}

}  // namespace
}  // namespace handover::app
