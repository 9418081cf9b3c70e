#include "app/experiment/experiment_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "app/report/json_writer.hpp"

namespace handover::app {

std::optional<double> settlingTime(const std::vector<double>& time, const std::vector<double>& error, double tol,
                                   double t_from) {
  if (time.size() != error.size()) throw std::invalid_argument("settlingTime: time and error differ in length");
  if (time.empty() || !(error.back() <= tol) || time.back() < t_from) return std::nullopt;
  // walk back from the end while the error stays within tolerance
  std::size_t i = error.size() - 1;
  while (i > 0 && error[i - 1] <= tol && time[i - 1] >= t_from) --i;
  return time[i];
}

ErrorStats errorStats(const std::vector<double>& v) {
  ErrorStats s;
  if (v.empty()) return s;
  double sq = 0.0;
  for (double x : v) {
    sq += x * x;
    s.max = std::max(s.max, x);
  }
  s.rms = std::sqrt(sq / static_cast<double>(v.size()));
  return s;
}

double rotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / M_PI;
}

ExperimentMetrics computeExperimentMetrics(const std::vector<ExperimentSample>& samples, const MetricThresholds& th) {
  if (samples.empty()) throw std::invalid_argument("computeExperimentMetrics: no samples");
  const std::size_t n = samples.size();
  std::vector<double> t(n), obs_p(n), obs_r(n), trk_p(n), trk_r(n), true_p(n), true_r(n), speed(n);
  std::vector<double> meas_p, meas_r;
  meas_p.reserve(n);
  meas_r.reserve(n);
  ExperimentMetrics m;
  for (std::size_t i = 0; i < n; ++i) {
    const ExperimentSample& s = samples[i];
    t[i] = s.time;
    obs_p[i] = (s.observed.translation() - s.object_true.translation()).norm();
    obs_r[i] = rotationErrorDeg(s.observed, s.object_true);
    if (s.measured_valid) {
      meas_p.push_back((s.observed.translation() - s.object_measured.translation()).norm());
      meas_r.push_back(rotationErrorDeg(s.observed, s.object_measured));
    }
    trk_p[i] = (s.tcp.translation() - s.reference.translation()).norm();
    trk_r[i] = rotationErrorDeg(s.tcp, s.reference);
    true_p[i] = (s.tcp.translation() - s.grasp_true.translation()).norm();
    true_r[i] = rotationErrorDeg(s.tcp, s.grasp_true);
    speed[i] = s.hand_speed;
    m.position_violations += s.position_violation;
    m.velocity_violations += s.velocity_violation;
    m.torque_violations += s.torque_violation;
    m.qp_failures += s.qp_failed;
    m.finger_object_contact_steps += s.finger_on_object;
    m.person_contact_steps += s.robot_touches_person;
  }
  m.obs_pos_vs_true = errorStats(obs_p);
  m.obs_rot_vs_true = errorStats(obs_r);
  m.obs_pos_vs_measured = errorStats(meas_p);
  m.obs_rot_vs_measured = errorStats(meas_r);
  m.track_pos = errorStats(trk_p);
  m.track_rot = errorStats(trk_r);
  m.true_pos = errorStats(true_p);
  m.true_rot = errorStats(true_r);
  m.final_pos_error = true_p.back();
  m.final_rot_error_deg = true_r.back();
  m.duration = t.back();

  // reached = both errors within tolerance, scaled to one signal <= 1
  std::vector<double> both(n);
  for (std::size_t i = 0; i < n; ++i) both[i] = std::max(true_p[i] / th.reach_pos, true_r[i] / th.reach_rot_deg);
  // the rest time is the start of the final stretch below the rest speed
  // (the hand also rests before it starts moving)
  m.hand_rest_time = settlingTime(t, speed, th.rest_speed - 1e-12);
  m.reached_time = settlingTime(t, both, 1.0);
  if (m.hand_rest_time && m.reached_time) m.rest_to_reached = *m.reached_time - *m.hand_rest_time;
  m.position_settle_time = settlingTime(t, true_p, th.reach_pos);
  m.orientation_settle_time = settlingTime(t, true_r, th.reach_rot_deg);
  if (m.position_settle_time && m.orientation_settle_time)
    m.orientation_first = *m.orientation_settle_time < *m.position_settle_time;
  return m;
}

namespace {
void stats(JsonWriter& w, const std::string& key, const ErrorStats& s) {
  w.beginObject(key).value("rms", s.rms).value("max", s.max).endObject();
}
std::optional<double> asNumber(const std::optional<bool>& b) {
  return b ? std::optional<double>(*b ? 1.0 : 0.0) : std::nullopt;
}
}  // namespace

std::string metricsToJson(const ExperimentMetrics& m, const std::string& controller) {
  JsonWriter w;
  w.beginObject();
  w.value("controller", controller);
  w.value("duration", m.duration);
  w.beginObject("observation_error");
  stats(w, "pos_vs_true_m", m.obs_pos_vs_true);
  stats(w, "rot_vs_true_deg", m.obs_rot_vs_true);
  stats(w, "pos_vs_measured_m", m.obs_pos_vs_measured);
  stats(w, "rot_vs_measured_deg", m.obs_rot_vs_measured);
  w.endObject();
  w.beginObject("tracking_error");
  stats(w, "pos_vs_reference_m", m.track_pos);
  stats(w, "rot_vs_reference_deg", m.track_rot);
  stats(w, "pos_vs_true_grasp_m", m.true_pos);
  stats(w, "rot_vs_true_grasp_deg", m.true_rot);
  w.value("final_pos_m", m.final_pos_error);
  w.value("final_rot_deg", m.final_rot_error_deg);
  w.endObject();
  w.value("hand_rest_time", m.hand_rest_time);
  w.value("reached_time", m.reached_time);
  w.value("rest_to_reached", m.rest_to_reached);
  w.value("position_settle_time", m.position_settle_time);
  w.value("orientation_settle_time", m.orientation_settle_time);
  if (m.orientation_first)
    w.value("orientation_first", *m.orientation_first);
  else
    w.value("orientation_first", asNumber(m.orientation_first));  // null
  w.beginObject("limit_violations")
      .value("position", m.position_violations)
      .value("velocity", m.velocity_violations)
      .value("torque", m.torque_violations)
      .endObject();
  w.value("qp_failures", m.qp_failures);
  w.beginObject("contact_steps")
      .value("finger_object", m.finger_object_contact_steps)
      .value("robot_person", m.person_contact_steps)
      .endObject();
  w.endObject();
  return w.str();
}

}  // namespace handover::app
