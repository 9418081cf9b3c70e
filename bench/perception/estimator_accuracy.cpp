// Accuracy of the perception estimator on recorded (or synthetic) human
// motion: the motion is replayed at 1 kHz through the simulated pose sensor
// with a given rate, latency and noise, and the estimate at each instant is
// compared with where the hand truly is at that instant (so latency counts as
// error). Compares the motion models of config/perception.yaml (first-order
// smoothing, the constant-velocity Kalman filter with and without
// prediction). Not a speed benchmark: docs/perception.md quotes its numbers.
//
//   estimator_accuracy [POSES.csv | MAPPING.yaml DATA_DIR] [key=value ...]
//     POSES.csv     a pose CSV (docs/perception.md);
//     MAPPING.yaml  a recording mapping (docs/recordings.md) and its data
//                   folder: the whole recording is replayed (its window and
//                   hold are ignored), e.g. scenes/recordings/kth_handover.yaml
//                   with the KTH human-human handover;
//     neither       synthetic minimum-jerk reaches.
//   key=value overrides the Kalman filter of config/perception.yaml:
//   acceleration_noise, angular_acceleration_noise, position_noise,
//   rotation_noise_deg, prediction_horizon, rotation_prediction_horizon;
//   prediction_significance; tolerance (of the gates).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "perception/csv_pose_source.hpp"
#include "perception/perception_config.hpp"
#include "perception/perception_estimator.hpp"
#include "perception/recording/recording_import.hpp"
#include "perception/simulated_pose_sensor.hpp"

using namespace handover;
using namespace handover::perception;

namespace {

// minimum-jerk reaches between a few points, at rest in between (1 kHz)
std::vector<PoseSample> syntheticMotion() {
  const Eigen::Vector3d pts[] = {{0.9, 0.25, 0.1}, {0.55, 0.05, 0.3}, {0.6, -0.1, 0.25}, {0.85, 0.3, 0.15},
                                 {0.5, 0.1, 0.4}};
  const double yaw[] = {0.0, 0.8, 0.2, -0.5, 0.3};
  std::vector<PoseSample> out;
  double t = 0.0;
  for (std::size_t i = 0; i + 1 < std::size(pts); ++i) {
    const double T = 0.8 + 0.3 * static_cast<double>(i % 2), rest = 0.5;
    for (double s = 0.0; s < T + rest; s += 0.001) {
      const double u = std::min(1.0, s / T), m = u * u * u * (10 - 15 * u + 6 * u * u);
      PoseSample p;
      p.stamp = t + s;
      p.hand.position = pts[i] + m * (pts[i + 1] - pts[i]);
      p.hand.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw[i] + m * (yaw[i + 1] - yaw[i]), Eigen::Vector3d::UnitZ()));
      p.forearm = p.upper_arm = p.hand;
      out.push_back(p);
    }
    t += T + rest;
  }
  return out;
}

// the truth at time t, interpolated between the recording's samples
io::HumanBodyPoses truthAt(const std::vector<PoseSample>& rec, double t, std::size_t& i) {
  while (i + 1 < rec.size() && rec[i + 1].stamp <= t) ++i;
  const PoseSample& a = rec[i];
  const PoseSample& b = rec[std::min(i + 1, rec.size() - 1)];
  const double u = b.stamp > a.stamp ? std::clamp((t - a.stamp) / (b.stamp - a.stamp), 0.0, 1.0) : 0.0;
  const auto lerp = [u](const Pose& x, const Pose& y) {
    Pose p;
    p.position = x.position + u * (y.position - x.position);
    p.orientation = x.orientation.slerp(u, y.orientation);
    return p.isometry();
  };
  io::HumanBodyPoses h;
  h.hand = lerp(a.hand, b.hand);
  h.forearm = lerp(a.forearm, b.forearm);
  h.upper_arm = lerp(a.upper_arm, b.upper_arm);
  return h;
}

struct Errors {
  double pos_rms = 0, pos_p95 = 0, pos_max = 0, rot_rms = 0, rot_p95 = 0;
  long rejected = 0;
  RejectCounts why;
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

Errors replay(const std::vector<PoseSample>& rec, const SensorSettings& sensor, const EstimatorSettings& est_settings,
              std::uint64_t seed) {
  SimulatedPoseSensor s(sensor, seed);
  PerceptionEstimator est(est_settings);
  std::vector<double> ep, er;
  std::size_t i = 0;
  const double t0 = rec.front().stamp, t1 = rec.back().stamp;
  for (double t = t0; t <= t1; t += 0.001) {
    const io::HumanBodyPoses truth = truthAt(rec, t, i);
    s.observe(t, truth);
    est.update(t, s);
    const PerceptionEstimate& e = est.estimate(t, ObjectHolder::Person);
    if (!e.human.valid || t < t0 + 0.5) continue;  // judged once the estimate has settled
    ep.push_back((e.human.hand.translation() - truth.hand.translation()).norm());
    er.push_back(Eigen::AngleAxisd(e.human.hand.linear().transpose() * truth.hand.linear()).angle() * 180.0 / M_PI);
  }
  Errors r;
  double sp = 0, sr = 0;
  for (double x : ep) sp += x * x;
  for (double x : er) sr += x * x;
  r.pos_rms = std::sqrt(sp / std::max<std::size_t>(1, ep.size())) * 1e3;
  r.pos_p95 = percentile(ep, 0.95) * 1e3;
  r.pos_max = ep.empty() ? 0.0 : *std::max_element(ep.begin(), ep.end()) * 1e3;
  r.rot_rms = std::sqrt(sr / std::max<std::size_t>(1, er.size()));
  r.rot_p95 = percentile(er, 0.95);
  r.rejected = est.rejected();
  r.why = est.rejects();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<PoseSample> rec;
  std::vector<std::string> files;
  EstimatorSettings product = loadPerceptionConfig(defaultPerceptionConfigPath()).estimator;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const std::size_t eq = a.find('=');
    if (eq == std::string::npos) {
      files.push_back(a);
      continue;
    }
    const std::string key = a.substr(0, eq);
    const double v = std::atof(a.c_str() + eq + 1);
    if (key == "acceleration_noise") product.filter.acceleration_noise = v;
    else if (key == "angular_acceleration_noise") product.filter.angular_acceleration_noise = v;
    else if (key == "position_noise") product.filter.position_noise = v;
    else if (key == "rotation_noise_deg") product.filter.rotation_noise = v * M_PI / 180.0;
    else if (key == "prediction_horizon") product.prediction_horizon = v;
    else if (key == "rotation_prediction_horizon") product.rotation_prediction_horizon = v;
    else if (key == "tolerance") product.gate.tolerance = v;
    else if (key == "prediction_significance") product.prediction_significance = v;
    else {
      std::fprintf(stderr, "unknown setting %s\n", key.c_str());
      return 2;
    }
  }
  try {
    if (files.empty()) {
      rec = syntheticMotion();
    } else if (files.size() == 2) {
      recording::RecordingMapping m = recording::loadRecordingMapping(files[0]);
      m.window_start = 0.0;
      m.window_end.reset();
      m.hold_end = 0.0;
      rec = recording::importRecording(m, files[1]).samples;
    } else {
      rec = readPoseCsv(files[0]);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  if (rec.size() < 2) {
    std::fprintf(stderr, "need at least two samples\n");
    return 2;
  }
  struct Model {
    const char* name;
    EstimatorSettings s;
  };
  std::vector<Model> models;
  EstimatorSettings smooth = product;
  smooth.model = MotionModel::kSmoothing;
  models.push_back({"smoothing (before)", smooth});
  EstimatorSettings kf0 = product;
  kf0.model = MotionModel::kKalman;
  kf0.prediction_horizon = 0.0;
  kf0.rotation_prediction_horizon = 0.0;
  models.push_back({"kalman, no prediction", kf0});
  EstimatorSettings kf = product;
  kf.model = MotionModel::kKalman;
  models.push_back({"kalman, predicted", kf});

  struct Case {
    double rate, latency, pos, rot_deg;
  };
  const Case cases[] = {{60, 0.0, 0.001, 0.5}, {60, 0.05, 0.003, 2.0}, {60, 0.1, 0.003, 2.0},
                        {60, 0.2, 0.003, 2.0}, {60, 0.2, 0.01, 5.0},   {30, 0.1, 0.003, 2.0},
                        {120, 0.0, 0.01, 5.0}, {60, 0.5, 0.003, 2.0}};
  std::printf("%s: %zu samples over %.2f s; error of the hand estimate against the truth at the same instant\n",
              files.empty() ? "synthetic reaches" : files[0].c_str(), rec.size(), rec.back().stamp - rec.front().stamp);
  std::printf("%-6s %-8s %-12s | %-22s | %9s %9s %9s | %9s %9s | %s\n", "rate", "latency", "noise", "model",
              "pos rms", "pos p95", "pos max", "rot rms", "rot p95", "rejected");
  for (const Case& c : cases) {
    SensorSettings ss;
    ss.rate_hz = c.rate;
    ss.latency = c.latency;
    ss.noise_pos = c.pos;
    ss.noise_rot_deg = c.rot_deg;
    for (const Model& m : models) {
      // mean over a few noise seeds
      Errors sum;
      const int seeds = 4;
      for (int k = 0; k < seeds; ++k) {
        const Errors e = replay(rec, ss, m.s, static_cast<std::uint64_t>(k + 1));
        sum.pos_rms += e.pos_rms / seeds;
        sum.pos_p95 += e.pos_p95 / seeds;
        sum.pos_max = std::max(sum.pos_max, e.pos_max);
        sum.rot_rms += e.rot_rms / seeds;
        sum.rot_p95 += e.rot_p95 / seeds;
        sum.rejected += e.rejected;
        sum.why += e.why;
      }
      std::printf("%-6.0f %-8.3f %4.0f mm %3.1f d | %-22s | %6.1f mm %6.1f mm %6.1f mm | %5.2f deg %5.2f deg | %ld",
                  c.rate, c.latency, c.pos * 1e3, c.rot_deg, m.name, sum.pos_rms, sum.pos_p95, sum.pos_max,
                  sum.rot_rms, sum.rot_p95, sum.rejected);
      for (int k = 0; k < kRejectReasons; ++k)
        if (sum.why.count[k]) std::printf(" %s %ld", toString(static_cast<RejectReason>(k)), sum.why.count[k]);
      std::printf("\n");
    }
  }
  return 0;
}
