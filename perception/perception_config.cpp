#include "perception/perception_config.hpp"
#include "config/config_directory.hpp"

#include <cmath>

namespace handover::perception {

EstimatorSettings PerceptionConfig::defaults() {
  EstimatorSettings e;  // the Kalman filter, its prediction and the gates as shipped
  e.smoothing_time = 0.03;
  e.rotation_smoothing_time = 0.1;
  return e;
}

namespace {

void parseKalman(const YamlReader& k, PoseFilterSettings& f) {
  if (!k.isMap()) k.fail("expected a map of Kalman filter settings");
  if (auto v = k.optionalChild("position_noise")) f.position_noise = v->checkRange(v->asDouble(), 1e-5, 1.0);
  if (auto v = k.optionalChild("rotation_noise_deg"))
    f.rotation_noise = v->checkRange(v->asDouble(), 1e-3, 45.0) * M_PI / 180.0;
  if (auto v = k.optionalChild("acceleration_noise"))
    f.acceleration_noise = v->checkRange(v->asDouble(), 1e-3, 1e4);
  if (auto v = k.optionalChild("angular_acceleration_noise"))
    f.angular_acceleration_noise = v->checkRange(v->asDouble(), 1e-3, 1e4);
  if (auto v = k.optionalChild("initial_speed")) f.initial_speed = v->checkRange(v->asDouble(), 0.0, 100.0);
  if (auto v = k.optionalChild("noise_adaptation_time"))
    f.noise_adaptation_time = v->checkRange(v->asDouble(), 0.0, 100.0);
  if (auto v = k.optionalChild("initial_angular_speed"))
    f.initial_angular_speed = v->checkRange(v->asDouble(), 0.0, 100.0);
  k.finish();
}

void parseGates(const YamlReader& g, GateSettings& s) {
  if (!g.isMap()) g.fail("expected a map of plausibility gates");
  if (auto v = g.optionalChild("workspace_min")) s.workspace_min = v->asVector(3);
  if (auto v = g.optionalChild("workspace_max")) s.workspace_max = v->asVector(3);
  if ((s.workspace_max.array() <= s.workspace_min.array()).any() || !s.workspace_min.allFinite() ||
      !s.workspace_max.allFinite())
    g.fail("workspace_max must exceed workspace_min on every axis (finite, m)");
  if (auto v = g.optionalChild("max_speed")) s.max_speed = v->checkRange(v->asDouble(), 0.1, 100.0);
  if (auto v = g.optionalChild("max_acceleration")) s.max_acceleration = v->checkRange(v->asDouble(), 1.0, 1e4);
  if (auto v = g.optionalChild("max_jump")) s.max_jump = v->checkRange(v->asDouble(), 0.01, 100.0);
  if (auto v = g.optionalChild("tolerance")) s.tolerance = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = g.optionalChild("reseed_gap")) s.reseed_gap = v->checkRange(v->asDouble(), 0.0, 10.0);
  g.finish();
}

void parseReach(const YamlReader& r, ReachPredictorSettings& s) {
  if (!r.isMap()) r.fail("expected a map of reach-prediction settings");
  if (auto v = r.optionalChild("sample_period")) s.sample_period = v->checkRange(v->asDouble(), 1e-3, 0.2);
  if (auto v = r.optionalChild("window")) s.window = v->checkRange(v->asDouble(), 0.5, 20.0);
  if (auto v = r.optionalChild("rest_speed")) s.rest_speed = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = r.optionalChild("onset_speed")) s.onset_speed = v->checkRange(v->asDouble(), 0.0, 2.0);
  if (s.onset_speed < s.rest_speed) r.fail("onset_speed must be at least rest_speed");
  if (auto v = r.optionalChild("min_duration")) s.min_duration = v->checkRange(v->asDouble(), 0.05, 10.0);
  if (auto v = r.optionalChild("max_duration")) s.max_duration = v->checkRange(v->asDouble(), 0.1, 20.0);
  if (s.max_duration <= s.min_duration) r.fail("max_duration must exceed min_duration");
  if (auto v = r.optionalChild("lead_start")) s.lead_start = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = r.optionalChild("lead_full")) s.lead_full = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (s.lead_full < s.lead_start) r.fail("lead_full must be at least lead_start");
  if (auto v = r.optionalChild("max_residual")) s.max_residual = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = r.optionalChild("restart_settle")) s.restart_settle = v->checkRange(v->asDouble(), 0.0, 2.0);
  r.finish();
}

}  // namespace

PerceptionConfig parsePerceptionConfig(const YamlReader& root) {
  PerceptionConfig c;
  EstimatorSettings& e = c.estimator;
  if (root.isNull()) return c;
  if (!root.isMap()) root.fail("expected a map of perception settings");
  if (auto v = root.optionalChild("max_gap")) e.max_gap = v->checkRange(v->asDouble(), 1e-3, 10.0);
  if (auto v = root.optionalChild("max_latency")) e.max_latency = v->checkRange(v->asDouble(), 0.0, 10.0);
  if (auto v = root.optionalChild("model"))
    e.model = v->asEnum({"kalman", "smoothing"}) == "kalman" ? MotionModel::kKalman : MotionModel::kSmoothing;
  if (auto v = root.optionalChild("prediction_horizon")) e.prediction_horizon = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = root.optionalChild("smooth_rotations")) e.smooth_rotations = v->asBool();
  if (auto v = root.optionalChild("prediction_significance"))
    e.prediction_significance = v->checkRange(v->asDouble(), 0.0, 10.0);
  if (auto v = root.optionalChild("rotation_prediction_horizon"))
    e.rotation_prediction_horizon = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = root.optionalChild("kalman")) parseKalman(*v, e.filter);
  if (auto v = root.optionalChild("smoothing_time")) e.smoothing_time = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = root.optionalChild("rotation_smoothing_time"))
    e.rotation_smoothing_time = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = root.optionalChild("gates")) parseGates(*v, e.gate);
  if (auto v = root.optionalChild("blend_time")) c.blend_time = v->checkRange(v->asDouble(), 0.0, 5.0);
  if (auto v = root.optionalChild("reach_prediction")) parseReach(*v, c.reach);
  c.reach.restart_gap = e.gate.reseed_gap;  // the gap after which the estimator restarts its track
  root.finish();
  return c;
}

PerceptionConfig loadPerceptionConfig(const std::string& path) {
  return parsePerceptionConfig(YamlReader::loadFile(path));
}

std::string defaultPerceptionConfigPath() { return configFile("perception.yaml"); }

}  // namespace handover::perception
