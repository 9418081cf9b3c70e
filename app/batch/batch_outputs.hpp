// The files of a batch (docs/outputs.md): results.csv, summary.json and
// report.md, written the same way by `batch`, `report` and `merge`, so a
// benchmark run in shards and merged gives the files of one unsharded run.
// Tooling only (not real-time safe).
#pragma once

#include <string>
#include <vector>

#include "app/report/batch_summary.hpp"

namespace handover::app {

/// Writes DIR/results.csv (runs in index order), then reads it back and
/// computes DIR/summary.json and DIR/report.md from what was read (the same
/// rounding whichever command wrote the rows). Throws OutputError
/// (app/report/output_files.hpp) naming the file when a write fails.
void writeBatchOutputs(const std::string& dir, std::vector<BatchEntry> entries, const ShardInfo& shard);

/// The runs of DIR/results.csv. Throws InputError naming the file.
std::vector<BatchEntry> readBatchResults(const std::string& dir);

/// The `shard` of DIR/summary.json ({1, 1, runs} when it has none). Throws
/// InputError naming the file.
ShardInfo readShardInfo(const std::string& dir);

/// `handover report DIR`: report.md again from DIR/results.csv (summary.json
/// and results.csv are left as they are).
void rewriteReport(const std::string& dir);

/// `handover merge DIR... --out OUT`: the shards of one batch into one set of
/// files. Every shard of 1..N must be there once, all of the same batch
/// (same N and run count), and together hold every run exactly once;
/// otherwise InputError says what is missing or repeated.
void mergeBatches(const std::vector<std::string>& dirs, const std::string& out_dir);

}  // namespace handover::app
