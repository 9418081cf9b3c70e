// Aggregates of a batch of runs: DIR/results.csv (a row a run) and
// DIR/summary.json (design-notes section 4, plus the HandoverSim measures).
#pragma once

#include <string>
#include <vector>

#include "app/report/run_summary.hpp"

namespace handover::app {

/// One finished run of a batch.
struct BatchEntry {
  std::string scenario_file;  ///< path given on the command line
  int variant = 0;            ///< 0 = the file as written; 1..N = --vary variants
  unsigned long seed = 0;     ///< noise / variation seed used
  RunSummary summary;
};

/// The header of results.csv (column names are a contract, documented in docs/outputs.md).
std::string resultsCsvHeader();
std::string resultsCsvRow(const BatchEntry& e);

/// summary.json of a batch: runs, success_rate, count and rate of each outcome,
/// means over successes (time_to_grasp, total_time, hand_still_to_grasp),
/// smallest min_human_distance, limit violations and QP failures in total.
std::string batchSummaryJson(const std::vector<BatchEntry>& entries);

/// The outcome names in judgement order.
const std::vector<std::string>& outcomeNames();

}  // namespace handover::app
