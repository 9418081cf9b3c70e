#include "app/batch/batch_outputs.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "app/report/benchmark_report.hpp"
#include "app/report/output_files.hpp"
#include "config/input_error.hpp"

namespace handover::app {

namespace fs = std::filesystem;

namespace {

void writeFile(const fs::path& path, const std::string& text) { writeFileChecked(path.string(), text); }

std::string readFile(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path.string() + ": cannot read (is this a batch output folder?)");
  std::ostringstream os;
  os << f.rdbuf();
  return os.str();
}

std::string reportTitle(std::size_t runs) { return "Handover benchmark report (" + std::to_string(runs) + " runs)"; }

}  // namespace

void writeBatchOutputs(const std::string& dir, std::vector<BatchEntry> entries, const ShardInfo& shard) {
  prepareOutputDir(dir);
  std::stable_sort(entries.begin(), entries.end(), [](const BatchEntry& a, const BatchEntry& b) { return a.index < b.index; });
  const fs::path csv = fs::path(dir) / "results.csv";
  writeFile(csv, resultsCsv(entries));
  const std::vector<BatchEntry> rows = parseResultsCsv(readFile(csv), csv.string());
  writeFile(fs::path(dir) / "summary.json", batchSummaryJson(rows, &shard));
  writeFile(fs::path(dir) / "report.md", benchmarkReportMarkdown(rows, reportTitle(rows.size())));
}

std::vector<BatchEntry> readBatchResults(const std::string& dir) {
  const fs::path csv = fs::path(dir) / "results.csv";
  return parseResultsCsv(readFile(csv), csv.string());
}

ShardInfo readShardInfo(const std::string& dir) {
  const fs::path path = fs::path(dir) / "summary.json";
  const std::string text = readFile(path);
  ShardInfo info;
  try {
    const YAML::Node root = YAML::Load(text);  // JSON is YAML
    info.runs_total = root["runs"].as<int>();
    if (const YAML::Node s = root["shard"]) {
      info.index = s["index"].as<int>();
      info.count = s["count"].as<int>();
      info.runs_total = s["runs_total"].as<int>();
    }
  } catch (const YAML::Exception& e) {
    throw InputError(path.string() + ": not a batch summary.json: " + e.msg);
  }
  return info;
}

void rewriteReport(const std::string& dir) {
  const std::vector<BatchEntry> rows = readBatchResults(dir);
  writeFile(fs::path(dir) / "report.md", benchmarkReportMarkdown(rows, reportTitle(rows.size())));
}

void mergeBatches(const std::vector<std::string>& dirs, const std::string& out_dir) {
  if (dirs.empty()) throw InputError("merge: no shard folders given");
  std::vector<BatchEntry> all;
  std::set<int> shards_seen;
  ShardInfo first;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const ShardInfo info = readShardInfo(dirs[i]);
    if (i == 0) first = info;
    if (info.count != first.count || info.runs_total != first.runs_total) {
      throw InputError(dirs[i] + ": shard " + std::to_string(info.index) + "/" + std::to_string(info.count) + " of " +
                       std::to_string(info.runs_total) + " runs does not belong with " + dirs[0] + " (shard " +
                       std::to_string(first.index) + "/" + std::to_string(first.count) + " of " +
                       std::to_string(first.runs_total) + " runs)");
    }
    if (!shards_seen.insert(info.index).second) {
      throw InputError(dirs[i] + ": shard " + std::to_string(info.index) + "/" + std::to_string(info.count) +
                       " is given twice");
    }
    for (BatchEntry& e : readBatchResults(dirs[i])) {
      if (e.index % info.count != info.index - 1) {
        throw InputError(dirs[i] + ": run " + std::to_string(e.index) + " does not belong to shard " +
                         std::to_string(info.index) + "/" + std::to_string(info.count));
      }
      all.push_back(std::move(e));
    }
  }
  std::string missing;
  for (int k = 1; k <= first.count; ++k) {
    if (!shards_seen.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(first.count);
  }
  if (!missing.empty()) throw InputError("merge: shard(s) " + missing + " missing");
  std::set<int> indices;
  for (const auto& e : all) {
    if (!indices.insert(e.index).second) throw InputError("merge: run " + std::to_string(e.index) + " appears twice");
  }
  if (static_cast<int>(all.size()) != first.runs_total) {
    throw InputError("merge: the shards hold " + std::to_string(all.size()) + " runs, the batch has " +
                     std::to_string(first.runs_total) + " (an unfinished shard?)");
  }
  writeBatchOutputs(out_dir, std::move(all), {1, 1, first.runs_total});
}

}  // namespace handover::app
