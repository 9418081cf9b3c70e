// Per-step costs of the scripted person and the perception pipeline, which
// run inside the 1 ms loop (simulation side and controller side).
#include <benchmark/benchmark.h>

#include <cmath>

#include "perception/observation_target.hpp"
#include "perception/perception_estimator.hpp"
#include "perception/pose_codec.hpp"
#include "perception/reach_predictor.hpp"
#include "perception/simulated_pose_sensor.hpp"
#include "scenes/human/scripted_human.hpp"
#include "scenes/scenario/scenario_parser.hpp"
#include "interfaces/minimum_jerk.hpp"

using namespace handover;

static void BM_ScriptedHumanStep(benchmark::State& state) {
  const auto sc = scenario::parseScenario(std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios/h2r_moving_target.yaml");
  human::ScriptedHuman h(sc);
  human::HumanFacts f;
  double t = 0.0;
  for (auto _ : state) {
    t += 0.001;
    if (t > 3.5) {  // stay within the reaches
      h.reset();
      t = 0.0;
    }
    benchmark::DoNotOptimize(h.step(t, f).poses.forearm);
  }
}
BENCHMARK(BM_ScriptedHumanStep);

static void BM_SensorObservePoll(benchmark::State& state) {
  perception::SensorSettings cfg;
  cfg.latency = 0.05;
  cfg.noise_pos = 0.002;
  cfg.noise_rot_deg = 1.0;
  perception::SimulatedPoseSensor s(cfg, 1);
  sim::HumanBodyPoses b;
  perception::PoseSample out;
  double t = 0.0;
  for (auto _ : state) {
    t += 0.001;
    s.observe(t, b);
    while (s.poll(t, out)) benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_SensorObservePoll);

static void BM_EstimatorAndTarget(benchmark::State& state) {
  perception::PerceptionEstimator est;
  perception::ObservationTarget target;
  target.select(perception::TargetSource::Object, 0.0);
  perception::PoseSample s;
  double t = 0.0;
  bool hand = false;
  for (auto _ : state) {
    t += 0.001;
    s.stamp = t;
    est.addSample(s);
    const auto& e = est.estimate(t, perception::ObjectHolder::Person);
    if (std::fmod(t, 1.0) < 0.001) target.select((hand = !hand) ? perception::TargetSource::Hand
                                                                : perception::TargetSource::Object, t);
    benchmark::DoNotOptimize(target.update(t, e).pose);
  }
}
BENCHMARK(BM_EstimatorAndTarget);

// One fit of the reach predictor (planning stage, once per kept sample during a reach): a
// 1.2 s minimum-jerk reach fed up to `state.range(0)` percent of its duration, then one more sample.
static void BM_ReachPredictorFit(benchmark::State& state) {
  const double t0 = 0.5, T = 1.2, until = t0 + T * state.range(0) / 100.0;
  const Eigen::Vector3d from(0.9, 0.2, 0.15), to(0.55, 0.05, 0.35);
  const auto pose = [&](double t) {
    Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
    x.translation() = from + minimumJerkPhase((t - t0) / T) * (to - from);
    return x;
  };
  const auto speed = [&](double t) { return (pose(t + 1e-4).translation() - pose(t).translation()).norm() / 1e-4; };
  perception::ReachPredictor p;
  for (double t = 0.0; t < until; t += 0.001) p.add(t, pose(t), speed(t));
  for (auto _ : state) {
    state.PauseTiming();
    perception::ReachPredictor q = p;  // the same history each time
    state.ResumeTiming();
    q.add(until + 0.02, pose(until + 0.02), speed(until + 0.02));
    benchmark::DoNotOptimize(q.prediction().end);
  }
}
BENCHMARK(BM_ReachPredictorFit)->Arg(50)->Arg(90);

static void BM_DecodeDatagram(benchmark::State& state) {
  perception::PoseSample s;
  s.stamp = 12.345678;
  s.hand.position = {0.55, 0.05, 0.3};
  char buf[perception::kMaxEncodedSample];
  perception::encodeSample(s, ',', buf, sizeof buf);
  perception::PoseSample out;
  for (auto _ : state) benchmark::DoNotOptimize(perception::decodeSample(buf, ',', out));
}
BENCHMARK(BM_DecodeDatagram);
