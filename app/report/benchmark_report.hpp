// The benchmark report of a batch (docs/benchmark.md): report.md, the
// tables a paper would print, overall and per category, computed from the
// runs as results.csv holds them, so a merged set of shards gives the same
// report as one unsharded batch. Reporting only (not real-time safe).
#pragma once

#include <string>
#include <vector>

#include "app/report/batch_summary.hpp"

namespace handover::app {

/// One group of runs, as a report row.
struct GroupStats {
  std::string name;
  int runs = 0;
  double met_rate = 0.0;  ///< share of runs whose `expect:` held (the benchmark's success: an abort expects `aborted`)
  double outcome_rate[kOutcomes] = {};  ///< share of each outcome, in outcomeNames() order
  // over runs whose outcome is success; NaN when there are none
  double time_to_grasp_median = 0.0, time_to_grasp_p90 = 0.0;
  double hand_still_median = 0.0, hand_still_p90 = 0.0;
  double total_time_median = 0.0, total_time_p90 = 0.0;
};

/// Statistics of `entries` under `name`.
GroupStats groupStats(const std::string& name, const std::vector<const BatchEntry*>& entries);

/// Nearest-rank percentile (q in [0, 1]) of `values` (sorted in place); NaN if empty.
double percentile(std::vector<double>& values, double q);

/// report.md: overall; by direction, grasp family, shape, behaviour,
/// placement, hand and height; direction x grasp x shape; the weakest
/// direction/grasp/shape/behaviour cells; totals of contacts, limit
/// violations and QP failures. Deterministic in the runs (no wall-clock data).
std::string benchmarkReportMarkdown(const std::vector<BatchEntry>& entries, const std::string& title);

/// compare.md: `before` against `after` (two batches, e.g. of the same
/// generated files before and after a change): per factor and per direction x
/// grasp x shape, runs and ok % of each, the change in points, and the
/// median hand-still-to-grasp; rows whose ok % fell by more than `worse_points`
/// are marked. Groups present in one batch only show "-" for the other.
std::string benchmarkComparisonMarkdown(const std::vector<BatchEntry>& before, const std::vector<BatchEntry>& after,
                                        const std::string& before_name, const std::string& after_name,
                                        double worse_points = 2.0);

}  // namespace handover::app
