// `handover batch`: many scenarios (and --vary variants) in parallel worker
// threads, each run fully independent (own simulator, controller, person).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "app/report/batch_summary.hpp"

namespace handover::app {

struct BatchOptions {
  std::vector<std::string> files;  ///< scenario files
  int jobs = 2;                    ///< worker threads
  int vary = 0;                    ///< variants per file (0 = the files as written)
  std::string out_dir = "out/batch";
  bool per_run_files = false;      ///< also write each run's summary.json and log.csv (no plots)
  bool progress = true;            ///< progress bar on stderr
  int shard_index = 1;             ///< run only shard K (1-based) of shard_count disjoint slices
  int shard_count = 1;             ///< 1 = the whole batch
};

/// Parses every file first (any bad file: InputError before anything runs),
/// then runs them all (or the runs of one shard: run i of the whole list
/// belongs to shard (i mod N) + 1); writes results.csv, summary.json and
/// report.md into out_dir (writeBatchOutputs). Runs that fault are recorded
/// with outcome "error" and their message.
std::vector<BatchEntry> runBatch(const BatchOptions& options, std::ostream& progress_out);

}  // namespace handover::app
