#include "app/report/batch_summary.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "app/report/json_writer.hpp"
#include "config/input_error.hpp"

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
  static const std::vector<std::string> names = {"success", "aborted",       "hand_contact", "object_drop",
                                                 "timeout", "no_perception", "unsafe",       "error"};
  return names;
}

std::string resultsCsvHeader() {
  return "scenario,variant,seed,mode,outcome,success,handovers,aborts,retries,time_to_grasp,"
         "hand_still_to_grasp,total_time,min_human_distance,human_contacts,object_dropped,"
         "limit_position,limit_velocity,limit_torque,qp_failures,grasp_error_pos,grasp_error_rot_deg,"
         "control_step_us_median,control_step_us_p99,control_step_us_max,realtime_factor,error,"
         "index,direction,grasp,shape,behaviour,placement,hand,height,category,expected_outcome,met,drop_time,drop_reason,qp_relaxed,limit_guard";
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
     << ',' << csvField(s.error_message) << ',' << e.index << ',' << e.category.direction << ','
     << e.category.grasp << ',' << e.category.shape << ',' << e.category.behaviour << ',' << e.category.placement
     << ',' << e.category.hand << ',' << e.category.height << ',' << scenario::categoryLabel(e.category) << ','
     << e.expected_outcome << ',' << (e.expectation_met ? 1 : 0) << ',' << num(s.drop_time) << ',' << s.drop_reason
     << ',' << s.qp_relaxed << ',' << s.limit_guard_steps;
  return os.str();
}

std::string resultsCsv(const std::vector<BatchEntry>& entries) {
  std::string out = resultsCsvHeader() + "\n";
  for (const auto& e : entries) out += resultsCsvRow(e) + "\n";
  return out;
}

namespace {

// one CSV record (RFC 4180 quoting); `pos` moves past it and its line end
std::vector<std::string> csvRecord(const std::string& text, std::size_t& pos, int& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  while (pos < text.size()) {
    const char c = text[pos++];
    if (quoted) {
      if (c == '"' && pos < text.size() && text[pos] == '"') {
        fields.back() += '"';
        ++pos;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c == '\n') {
      ++line;
      break;
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

std::vector<BatchEntry> parseResultsCsv(const std::string& text, const std::string& origin) {
  std::size_t pos = 0;
  int line = 1;
  const std::vector<std::string> header = csvRecord(text, pos, line);
  std::map<std::string, std::size_t> col;
  for (std::size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
  for (const char* need : {"scenario", "outcome", "index", "direction", "met"}) {
    if (!col.count(need)) {
      throw InputError(origin + ":1: not a results.csv of this version: no column '" + need + "'");
    }
  }
  std::vector<BatchEntry> entries;
  while (pos < text.size()) {
    const int at = line;
    const std::vector<std::string> f = csvRecord(text, pos, line);
    if (f.size() == 1 && f[0].empty()) continue;
    if (f.size() != header.size()) {
      throw InputError(origin + ":" + std::to_string(at) + ": " + std::to_string(f.size()) + " fields, the header has " +
                       std::to_string(header.size()));
    }
    auto get = [&](const char* name) -> std::string {
      auto it = col.find(name);
      return it == col.end() ? std::string() : f[it->second];
    };
    auto real = [&](const char* name) -> std::optional<double> {
      const std::string v = get(name);
      if (v.empty()) return std::nullopt;
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end) {
        throw InputError(origin + ":" + std::to_string(at) + ": column '" + name + "': not a number: '" + v + "'");
      }
      return d;
    };
    auto integer = [&](const char* name) { return static_cast<int>(real(name).value_or(0.0)); };
    BatchEntry e;
    RunSummary& s = e.summary;
    e.scenario_file = get("scenario");
    e.variant = integer("variant");
    e.seed = static_cast<unsigned long>(real("seed").value_or(0.0));
    e.index = integer("index");
    e.category = {get("direction"), get("grasp"), get("shape"), get("behaviour"), get("placement"), get("hand"), get("height")};
    e.expected_outcome = get("expected_outcome");
    e.expectation_met = get("met") == "1";
    s.scenario = e.scenario_file;
    s.mode = get("mode");
    s.outcome = get("outcome");
    s.error_message = get("error");
    s.handovers = integer("handovers");
    s.aborts = integer("aborts");
    s.retries = integer("retries");
    s.time_to_grasp = real("time_to_grasp");
    s.hand_still_to_grasp = real("hand_still_to_grasp");
    s.total_time = real("total_time");
    s.min_human_distance = real("min_human_distance").value_or(INFINITY);
    s.human_contacts = integer("human_contacts");
    s.object_dropped = get("object_dropped") == "1";
    s.drop_time = real("drop_time");
    s.drop_reason = get("drop_reason");
    s.limit_violations = {integer("limit_position"), integer("limit_velocity"), integer("limit_torque")};
    s.qp_failures = integer("qp_failures");
    s.qp_relaxed = integer("qp_relaxed");  // 0 in results of older versions
    s.limit_guard_steps = integer("limit_guard");  // 0 in results of older versions
    s.grasp_error_pos = real("grasp_error_pos");
    s.grasp_error_rot_deg = real("grasp_error_rot_deg");
    s.control_step_us = {real("control_step_us_median").value_or(0.0), real("control_step_us_p99").value_or(0.0),
                         real("control_step_us_max").value_or(0.0)};
    s.realtime_factor = real("realtime_factor").value_or(0.0);
    entries.push_back(std::move(e));
  }
  return entries;
}

std::string batchSummaryJson(const std::vector<BatchEntry>& entries, const ShardInfo* shard) {
  std::map<std::string, int> count;
  for (const auto& n : outcomeNames()) count[n] = 0;
  Mean ttg, total, still;
  double min_dist = INFINITY;
  int lim_pos = 0, lim_vel = 0, lim_tau = 0, qp = 0, relaxed = 0, guarded = 0, aborts = 0, retries = 0, contacts = 0;
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
    relaxed += s.qp_relaxed;
    guarded += s.limit_guard_steps;
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
  w.value("qp_relaxed", relaxed);
  w.value("limit_guard_steps", guarded);
  int met = 0;
  std::map<std::string, std::pair<int, int>> by_category;  // label -> (runs, met)
  for (const auto& e : entries) {
    met += e.expectation_met ? 1 : 0;
    auto& c = by_category[scenario::categoryLabel(e.category)];
    ++c.first;
    c.second += e.expectation_met ? 1 : 0;
  }
  w.value("expectation_met_rate", rate(met));
  w.beginObject("by_category");
  for (const auto& [label, c] : by_category) {
    w.beginObject(label).value("runs", c.first).value("expectation_met_rate", static_cast<double>(c.second) / c.first).endObject();
  }
  w.endObject();
  if (shard) {
    w.beginObject("shard").value("index", shard->index).value("count", shard->count).value("runs_total", shard->runs_total).endObject();
  }
  w.endObject();
  return w.str() + "\n";
}

}  // namespace handover::app
