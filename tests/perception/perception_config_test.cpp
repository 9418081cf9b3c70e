#include "perception/perception_config.hpp"

#include <gtest/gtest.h>

#include "config/input_error.hpp"

using namespace handover;
using namespace handover::perception;

namespace {
PerceptionConfig parse(const std::string& text) { return parsePerceptionConfig(YamlReader::loadString(text, "p.yaml")); }
std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(PerceptionConfig, ShippedFileIsTheDefaults) {
  const PerceptionConfig c = loadPerceptionConfig(defaultPerceptionConfigPath());
  const EstimatorSettings d = PerceptionConfig::defaults();
  EXPECT_EQ(c.estimator.model, MotionModel::kKalman);
  EXPECT_DOUBLE_EQ(c.estimator.max_latency, d.max_latency);
  EXPECT_DOUBLE_EQ(c.estimator.prediction_horizon, d.prediction_horizon);
  EXPECT_DOUBLE_EQ(c.estimator.rotation_prediction_horizon, d.rotation_prediction_horizon);
  EXPECT_DOUBLE_EQ(c.estimator.filter.acceleration_noise, d.filter.acceleration_noise);
  EXPECT_DOUBLE_EQ(c.estimator.filter.angular_acceleration_noise, d.filter.angular_acceleration_noise);
  EXPECT_NEAR(c.estimator.filter.rotation_noise, d.filter.rotation_noise, 1e-12);
  EXPECT_DOUBLE_EQ(c.estimator.prediction_significance, d.prediction_significance);
  EXPECT_EQ(c.estimator.smooth_rotations, d.smooth_rotations);
  EXPECT_DOUBLE_EQ(c.estimator.filter.noise_adaptation_time, d.filter.noise_adaptation_time);
  EXPECT_DOUBLE_EQ(c.estimator.gate.max_speed, d.gate.max_speed);
  EXPECT_DOUBLE_EQ(c.estimator.gate.max_acceleration, d.gate.max_acceleration);
  EXPECT_DOUBLE_EQ(c.estimator.gate.max_jump, d.gate.max_jump);
  EXPECT_DOUBLE_EQ(c.estimator.gate.tolerance, d.gate.tolerance);
  EXPECT_DOUBLE_EQ(c.estimator.gate.reseed_gap, d.gate.reseed_gap);
  EXPECT_EQ(c.estimator.gate.workspace_min, d.gate.workspace_min);
  EXPECT_EQ(c.estimator.gate.workspace_max, d.gate.workspace_max);
  // the contract allows latencies up to 1 s: they are compensated, not stale
  EXPECT_GE(c.estimator.max_latency, 1.0);
}

TEST(PerceptionConfig, ReadsEverySectionAndRejectsBadValues) {
  const PerceptionConfig c = parse(
      "model: smoothing\nprediction_horizon: 0.1\nkalman: {position_noise: 0.01, rotation_noise_deg: 3}\n"
      "gates: {max_speed: 2.0, max_jump: 0.2, workspace_min: [-1, -1, -1], workspace_max: [1, 1, 1]}\n");
  EXPECT_EQ(c.estimator.model, MotionModel::kSmoothing);
  EXPECT_DOUBLE_EQ(c.estimator.prediction_horizon, 0.1);
  EXPECT_DOUBLE_EQ(c.estimator.filter.position_noise, 0.01);
  EXPECT_NEAR(c.estimator.filter.rotation_noise, 3.0 * M_PI / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.estimator.gate.max_speed, 2.0);
  EXPECT_EQ(c.estimator.gate.workspace_max, Eigen::Vector3d(1, 1, 1));

  EXPECT_NE(errorOf("model: particle\n").find("model"), std::string::npos);
  EXPECT_NE(errorOf("gates: {max_sped: 2}\n").find("max_sped"), std::string::npos);
  EXPECT_NE(errorOf("gates: {max_speed: -1}\n").find("max_speed"), std::string::npos);
  EXPECT_NE(errorOf("gates: {workspace_min: [0, 0, 0], workspace_max: [1, 0, 1]}\n").find("workspace_max"),
            std::string::npos);
  EXPECT_NE(errorOf("kalman: {acceleration_noise: 0}\n").find("acceleration_noise"), std::string::npos);
  EXPECT_NE(errorOf("prediction_horizon: 2\n").find("prediction_horizon"), std::string::npos);
}

TEST(PerceptionConfig, TheReachIsLostAfterTheGapThatRestartsTheTrack) {
  // one gap for both: the estimator restarts its track at rest, the reach predictor loses the reach
  const PerceptionConfig c = parse("gates: {reseed_gap: 0.4}\nreach_prediction: {restart_settle: 0.2}\n");
  EXPECT_DOUBLE_EQ(c.reach.restart_gap, 0.4);
  EXPECT_DOUBLE_EQ(c.reach.restart_settle, 0.2);
  EXPECT_NE(errorOf("reach_prediction: {restart_settle: -1}\n").find("restart_settle"), std::string::npos);
  EXPECT_NE(errorOf("reach_prediction: {restart_gap: 0.3}\n").find("restart_gap"), std::string::npos);  // not its own key
}
