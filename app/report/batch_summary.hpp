// Aggregates of a batch of runs: DIR/results.csv (a row a run) and
// DIR/summary.json (design-notes section 4, plus the HandoverSim measures).
#pragma once

#include <string>
#include <vector>

#include "app/report/run_summary.hpp"
#include "scenes/scenario/scenario_category.hpp"

namespace handover::app {

/// One finished run of a batch.
struct BatchEntry {
  std::string scenario_file;  ///< path given on the command line
  int variant = 0;            ///< 0 = the file as written; 1..N = --vary variants
  unsigned long seed = 0;     ///< noise / variation seed used
  int index = 0;              ///< position in the whole batch's run list (kept by --shard)
  scenario::Category category;   ///< benchmark factors (docs/benchmark.md)
  std::string expected_outcome;  ///< the scenario's expect.outcome, "" if none
  bool expectation_met = true;   ///< every `expect:` line held
  RunSummary summary;
};

/// The header of results.csv (column names are a contract, documented in docs/outputs.md).
std::string resultsCsvHeader();
std::string resultsCsvRow(const BatchEntry& e);
/// Header and a row a run.
std::string resultsCsv(const std::vector<BatchEntry>& entries);
/// Reads results.csv text back (`origin` names it in messages); the columns
/// it needs are found by name, so a file with more columns reads too. Runs
/// come back with the summary fields results.csv holds (no states, no
/// expectation texts). Throws InputError naming origin and line.
std::vector<BatchEntry> parseResultsCsv(const std::string& text, const std::string& origin);

/// Which part of a whole batch a set of runs is (`batch --shard K/N`).
struct ShardInfo {
  int index = 1;       ///< K, 1-based
  int count = 1;       ///< N (1 = the whole batch)
  int runs_total = 0;  ///< runs of the whole batch, over all shards
};

/// summary.json of a batch: runs, success_rate, count and rate of each outcome,
/// means over successes (time_to_grasp, total_time, hand_still_to_grasp),
/// smallest min_human_distance, limit violations and QP failures in total;
/// expectation_met_rate and the same per category (`by_category`); `shard`
/// when `shard` is given.
std::string batchSummaryJson(const std::vector<BatchEntry>& entries, const ShardInfo* shard = nullptr);

/// The outcome names (success, aborted, hand_contact, object_drop, timeout,
/// no_perception, unsafe, error): the report's column order.
const std::vector<std::string>& outcomeNames();
constexpr int kOutcomes = 8;  ///< outcomeNames().size()

}  // namespace handover::app
