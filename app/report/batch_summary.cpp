#include "app/report/batch_summary.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "app/report/json_writer.hpp"

namespace handover::app {

namespace {

std::string num(const std::optional<double>& v) { return v ? JsonWriter::number(*v) : ""; }
std::string num(double v) { return std::isfinite(v) ? JsonWriter::number(v) : ""; }

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

struct Mean {
  double sum = 0.0;
  int n = 0;
  void add(const std::optional<double>& v) {
    if (v && std::isfinite(*v)) {
      sum += *v;
      ++n;
    }
  }
  std::optional<double> get() const { return n ? std::optional<double>(sum / n) : std::nullopt; }
};

}  // namespace

const std::vector<std::string>& outcomeNames() {
  static const std::vector<std::string> names = {"success", "aborted", "hand_contact", "object_drop",
                                                 "timeout", "unsafe",  "error"};
  return names;
}

std::string resultsCsvHeader() {
  return "scenario,variant,seed,mode,outcome,success,handovers,aborts,retries,time_to_grasp,"
         "hand_still_to_grasp,total_time,min_human_distance,human_contacts,object_dropped,"
         "limit_position,limit_velocity,limit_torque,qp_failures,grasp_error_pos,grasp_error_rot_deg,"
         "control_step_us_median,control_step_us_p99,control_step_us_max,realtime_factor,error";
}

std::string resultsCsvRow(const BatchEntry& e) {
  const RunSummary& s = e.summary;
  std::ostringstream os;
  os << csvField(e.scenario_file) << ',' << e.variant << ',' << e.seed << ',' << s.mode << ',' << s.outcome
     << ',' << (s.success() ? 1 : 0) << ',' << s.handovers << ',' << s.aborts << ',' << s.retries << ','
     << num(s.time_to_grasp) << ',' << num(s.hand_still_to_grasp) << ',' << num(s.total_time) << ','
     << num(s.min_human_distance) << ',' << s.human_contacts << ',' << (s.object_dropped ? 1 : 0) << ','
     << s.limit_violations.position << ',' << s.limit_violations.velocity << ','
     << s.limit_violations.torque << ',' << s.qp_failures << ',' << num(s.grasp_error_pos) << ','
     << num(s.grasp_error_rot_deg) << ',' << num(s.control_step_us.median) << ','
     << num(s.control_step_us.p99) << ',' << num(s.control_step_us.max) << ',' << num(s.realtime_factor)
     << ',' << csvField(s.error_message);
  return os.str();
}

std::string batchSummaryJson(const std::vector<BatchEntry>& entries) {
  std::map<std::string, int> count;
  for (const auto& n : outcomeNames()) count[n] = 0;
  Mean ttg, total, still;
  double min_dist = INFINITY;
  int lim_pos = 0, lim_vel = 0, lim_tau = 0, qp = 0, aborts = 0, retries = 0, contacts = 0;
  for (const auto& e : entries) {
    const RunSummary& s = e.summary;
    ++count[s.outcome];
    if (s.success()) {
      ttg.add(s.time_to_grasp);
      total.add(s.total_time);
      still.add(s.hand_still_to_grasp);
    }
    if (std::isfinite(s.min_human_distance)) min_dist = std::min(min_dist, s.min_human_distance);
    lim_pos += s.limit_violations.position;
    lim_vel += s.limit_violations.velocity;
    lim_tau += s.limit_violations.torque;
    qp += s.qp_failures;
    aborts += s.aborts;
    retries += s.retries;
    contacts += s.human_contacts;
  }
  const int n = static_cast<int>(entries.size());
  const auto rate = [n](int k) { return n ? static_cast<double>(k) / n : 0.0; };

  JsonWriter w;
  w.beginObject();
  w.value("runs", n).value("success_rate", rate(count["success"]));
  w.beginObject("counts");
  for (const auto& o : outcomeNames()) w.value(o, count[o]);
  w.endObject();
  w.beginObject("rates");
  for (const auto& o : outcomeNames()) w.value(o, rate(count[o]));
  w.endObject();
  // HandoverSim's failure shares (of all runs)
  w.value("hand_contact_rate", rate(count["hand_contact"]))
      .value("drop_rate", rate(count["object_drop"]))
      .value("timeout_rate", rate(count["timeout"]));
  w.beginObject("mean_over_successes")
      .value("time_to_grasp", ttg.get())
      .value("total_time", total.get())
      .value("hand_still_to_grasp", still.get())
      .endObject();
  w.value("min_human_distance", std::isfinite(min_dist) ? std::optional<double>(min_dist) : std::nullopt);
  w.value("human_contacts", contacts).value("aborts", aborts).value("retries", retries);
  w.beginObject("limit_violations").value("position", lim_pos).value("velocity", lim_vel).value("torque", lim_tau).endObject();
  w.value("qp_failures", qp);
  w.endObject();
  return w.str() + "\n";
}

}  // namespace handover::app
