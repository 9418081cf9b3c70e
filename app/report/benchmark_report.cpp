#include "app/report/benchmark_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>

namespace handover::app {

namespace {

using Key = std::function<std::string(const BatchEntry&)>;

std::string pct(double r) {
  char b[16];
  std::snprintf(b, sizeof b, "%.1f", 100.0 * r);
  return b;
}
std::string sec(double v) {
  if (!std::isfinite(v)) return "-";
  char b[16];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

const char* kHeader =
    "| group | runs | ok % | success % | aborted % | contact % | drop % | timeout % | blind % | unsafe % | error % "
    "| grasp s (med/p90) | hand still to grasp s (med/p90) | total s (med/p90) |\n"
    "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";

std::string row(const GroupStats& g) {
  std::ostringstream os;
  os << "| " << g.name << " | " << g.runs << " | " << pct(g.met_rate);
  for (int i = 0; i < kOutcomes; ++i) os << " | " << pct(g.outcome_rate[i]);
  os << " | " << sec(g.time_to_grasp_median) << " / " << sec(g.time_to_grasp_p90) << " | " << sec(g.hand_still_median)
     << " / " << sec(g.hand_still_p90) << " | " << sec(g.total_time_median) << " / " << sec(g.total_time_p90) << " |\n";
  return os.str();
}

std::map<std::string, std::vector<const BatchEntry*>> groupBy(const std::vector<BatchEntry>& entries, const Key& key) {
  std::map<std::string, std::vector<const BatchEntry*>> groups;
  for (const auto& e : entries) groups[key(e)].push_back(&e);
  return groups;
}

std::string table(const std::string& heading, const std::vector<BatchEntry>& entries, const Key& key) {
  std::string out = "## " + heading + "\n\n" + kHeader;
  for (const auto& [name, members] : groupBy(entries, key)) out += row(groupStats(name, members));
  return out + "\n";
}

}  // namespace

double percentile(std::vector<double>& values, double q) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const std::size_t rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

GroupStats groupStats(const std::string& name, const std::vector<const BatchEntry*>& entries) {
  GroupStats g;
  g.name = name;
  g.runs = static_cast<int>(entries.size());
  std::vector<double> ttg, still, total;
  int met = 0;
  int count[kOutcomes] = {};
  const auto& names = outcomeNames();
  for (const BatchEntry* e : entries) {
    met += e->expectation_met ? 1 : 0;
    const auto it = std::find(names.begin(), names.end(), e->summary.outcome);
    if (it != names.end()) ++count[it - names.begin()];
    if (!e->summary.success()) continue;
    if (e->summary.time_to_grasp) ttg.push_back(*e->summary.time_to_grasp);
    if (e->summary.hand_still_to_grasp) still.push_back(*e->summary.hand_still_to_grasp);
    if (e->summary.total_time) total.push_back(*e->summary.total_time);
  }
  const double n = std::max(1, g.runs);
  g.met_rate = met / n;
  for (int i = 0; i < kOutcomes; ++i) g.outcome_rate[i] = count[i] / n;
  g.time_to_grasp_median = percentile(ttg, 0.5);
  g.time_to_grasp_p90 = percentile(ttg, 0.9);
  g.hand_still_median = percentile(still, 0.5);
  g.hand_still_p90 = percentile(still, 0.9);
  g.total_time_median = percentile(total, 0.5);
  g.total_time_p90 = percentile(total, 0.9);
  return g;
}

std::string benchmarkReportMarkdown(const std::vector<BatchEntry>& entries, const std::string& title) {
  std::ostringstream md;
  md << "# " << title << "\n\n";
  md << "Runs: " << entries.size()
     << ". **ok** = the run ended as its scenario expects (`expect:`; a person who leaves for good expects "
        "`aborted`); the outcome columns are shares of all runs in the row (they add up to 100 %); times are "
        "medians / 90th percentiles over runs whose outcome is `success`. Categories: docs/benchmark.md.\n\n";
  std::vector<const BatchEntry*> all;
  for (const auto& e : entries) all.push_back(&e);
  md << "## Overall\n\n" << kHeader << row(groupStats("all", all)) << "\n";
  md << table("By direction", entries, [](const BatchEntry& e) { return e.category.direction; });
  md << table("By grasp family", entries, [](const BatchEntry& e) { return e.category.grasp; });
  md << table("By shape", entries, [](const BatchEntry& e) { return e.category.shape; });
  md << table("By behaviour", entries, [](const BatchEntry& e) { return e.category.behaviour; });
  md << table("By where the person stands", entries, [](const BatchEntry& e) { return e.category.placement; });
  md << table("By hand", entries, [](const BatchEntry& e) { return e.category.hand; });
  md << table("By height of the handover", entries, [](const BatchEntry& e) { return e.category.height; });
  md << table("Direction x grasp family x shape", entries, [](const BatchEntry& e) {
    return e.category.direction + "/" + e.category.grasp + "/" + e.category.shape;
  });

  // the weakest full categories with enough runs to mean something
  std::vector<GroupStats> cells;
  for (const auto& [name, members] :
       groupBy(entries, [](const BatchEntry& e) { return scenario::categoryLabel(e.category); })) {
    if (members.size() >= 3) cells.push_back(groupStats(name, members));
  }
  std::stable_sort(cells.begin(), cells.end(),
                   [](const GroupStats& a, const GroupStats& b) { return a.met_rate < b.met_rate; });
  md << "## Weakest categories (direction/grasp/shape/behaviour, at least 3 runs)\n\n" << kHeader;
  for (std::size_t i = 0; i < cells.size() && i < 15; ++i) md << row(cells[i]);
  md << "\n";

  int contacts = 0, lim_pos = 0, lim_vel = 0, lim_tau = 0, qp = 0, relaxed = 0, guarded = 0, contact_runs = 0, drops = 0;
  for (const auto& e : entries) {
    contacts += e.summary.human_contacts;
    contact_runs += e.summary.human_contacts > 0 ? 1 : 0;
    drops += e.summary.object_dropped ? 1 : 0;
    lim_pos += e.summary.limit_violations.position;
    lim_vel += e.summary.limit_violations.velocity;
    lim_tau += e.summary.limit_violations.torque;
    qp += e.summary.qp_failures;
    relaxed += e.summary.qp_relaxed;
    guarded += e.summary.limit_guard_steps;
  }
  md << "## Safety totals\n\n"
     << "| runs with a person contact | contacts | runs with the object dropped | limit-violation steps "
        "(position / velocity / torque) | QP failures | steps with collision rows relaxed | steps the limit guard "
        "changed |\n|---:|---:|---:|---|---:|---:|---:|\n"
     << "| " << contact_runs << " | " << contacts << " | " << drops << " | " << lim_pos << " / " << lim_vel << " / "
     << lim_tau << " | " << qp << " | " << relaxed << " | " << guarded << " |\n";
  return md.str();
}

namespace {

std::string comparisonTable(const std::string& heading, const std::vector<BatchEntry>& before,
                            const std::vector<BatchEntry>& after, const Key& key, double worse_points) {
  const auto b = groupBy(before, key), a = groupBy(after, key);
  std::map<std::string, int> names;
  for (const auto& [n, _] : b) names[n] = 0;
  for (const auto& [n, _] : a) names[n] = 0;
  std::ostringstream os;
  os << "## " << heading << "\n\n"
     << "| group | runs before | ok % before | runs after | ok % after | change (points) | hand still to grasp "
        "s, median before / after |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& [name, _] : names) {
    const auto ib = b.find(name), ia = a.find(name);
    const GroupStats gb = ib != b.end() ? groupStats(name, ib->second) : GroupStats{};
    const GroupStats ga = ia != a.end() ? groupStats(name, ia->second) : GroupStats{};
    const bool both = ib != b.end() && ia != a.end();
    const double change = 100.0 * (ga.met_rate - gb.met_rate);
    char delta[32] = "-";
    if (both) std::snprintf(delta, sizeof delta, "%+.1f%s", change, change < -worse_points ? " **worse**" : "");
    os << "| " << name << " | " << (ib != b.end() ? std::to_string(gb.runs) : "-") << " | "
       << (ib != b.end() ? pct(gb.met_rate) : "-") << " | " << (ia != a.end() ? std::to_string(ga.runs) : "-") << " | "
       << (ia != a.end() ? pct(ga.met_rate) : "-") << " | " << delta << " | "
       << (ib != b.end() ? sec(gb.hand_still_median) : "-") << " / " << (ia != a.end() ? sec(ga.hand_still_median) : "-")
       << " |\n";
  }
  return os.str() + "\n";
}

}  // namespace

std::string benchmarkComparisonMarkdown(const std::vector<BatchEntry>& before, const std::vector<BatchEntry>& after,
                                        const std::string& before_name, const std::string& after_name,
                                        double worse_points) {
  std::ostringstream md;
  md << "# Benchmark comparison\n\nbefore: `" << before_name << "` (" << before.size() << " runs); after: `"
     << after_name << "` (" << after.size() << " runs). **ok** = the run ended as its scenario expects. Rows whose "
     << "ok % fell by more than " << worse_points << " points are marked **worse**: a change that helps one "
     << "category and costs another is not a fix.\n\n";
  const Key all = [](const BatchEntry&) { return std::string("all"); };
  md << comparisonTable("Overall", before, after, all, worse_points);
  md << comparisonTable("By direction", before, after, [](const BatchEntry& e) { return e.category.direction; }, worse_points);
  md << comparisonTable("By grasp family", before, after, [](const BatchEntry& e) { return e.category.grasp; }, worse_points);
  md << comparisonTable("By shape", before, after, [](const BatchEntry& e) { return e.category.shape; }, worse_points);
  md << comparisonTable("By behaviour", before, after, [](const BatchEntry& e) { return e.category.behaviour; }, worse_points);
  md << comparisonTable("By where the person stands", before, after,
                        [](const BatchEntry& e) { return e.category.placement; }, worse_points);
  md << comparisonTable("Direction x grasp family x shape", before, after, [](const BatchEntry& e) {
    return e.category.direction + "/" + e.category.grasp + "/" + e.category.shape;
  }, worse_points);
  return md.str();
}

}  // namespace handover::app
