#include "app/batch/batch_runner.hpp"
#include "app/report/output_files.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "app/batch/batch_outputs.hpp"
#include "app/batch/scenario_variation.hpp"
#include "app/run/run_scenario.hpp"
#include "app/validate/scenario_validation.hpp"
#include "config/input_error.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace handover::app {

namespace {

struct Job {
  scenario::Scenario scenario;
  BatchEntry entry;
};

std::string duration(double s) {
  char b[32];
  if (s < 60) std::snprintf(b, sizeof b, "%ds", static_cast<int>(s + 0.5));
  else std::snprintf(b, sizeof b, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  return b;
}


}  // namespace

std::vector<BatchEntry> runBatch(const BatchOptions& opt, std::ostream& out) {
  // parse everything first: bad input fails the batch before it starts
  if (opt.shard_count < 1 || opt.shard_index < 1 || opt.shard_index > opt.shard_count) {
    throw InputError("--shard " + std::to_string(opt.shard_index) + "/" + std::to_string(opt.shard_count) +
                     ": K must be in 1..N");
  }
  std::vector<Job> jobs;
  int runs_total = 0;
  auto add = [&](scenario::Scenario sc, const std::string& file, int variant) {
    const int index = runs_total++;
    if (index % opt.shard_count != opt.shard_index - 1) return;
    Job j{std::move(sc), {}};
    j.entry.scenario_file = file;
    j.entry.variant = variant;
    j.entry.index = index;
    j.entry.seed = static_cast<unsigned long>(j.scenario.seed);
    j.entry.category = scenario::categoryOf(j.scenario);
    j.entry.expected_outcome = j.scenario.expect.outcome.value_or("");
    jobs.push_back(std::move(j));
  };
  for (const auto& file : opt.files) {
    const scenario::Scenario base = loadValidScenario(file);
    if (opt.vary <= 0) add(base, file, 0);
    for (int k = 1; k <= opt.vary; ++k) add(makeVariant(base, k), file, k);
  }

  prepareOutputDir(opt.out_dir);
  std::atomic<std::size_t> next{0};
  std::atomic<int> finished{0}, as_expected{0};
  std::mutex print_mutex;
  const auto t0 = std::chrono::steady_clock::now();
  const bool tty = isatty(STDERR_FILENO) != 0;
  int last_decile = -1;

  auto report = [&]() {
    if (!opt.progress) return;
    const int done = finished.load();
    const int n = static_cast<int>(jobs.size());
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double eta = done > 0 ? elapsed / done * (n - done) : 0.0;
    const int width = 30;
    const int fill = n ? done * width / n : width;
    std::string bar(static_cast<std::size_t>(fill), '#');
    bar.resize(width, '.');
    char line[200];
    std::snprintf(line, sizeof line, "[%s] %d/%d runs, %d as expected, elapsed %s, ETA %s", bar.c_str(), done, n,
                  as_expected.load(), duration(elapsed).c_str(), done ? duration(eta).c_str() : "?");
    if (tty) {
      out << "\r" << line << (done == n ? "\n" : "") << std::flush;
    } else {
      // not a terminal (CI, a file): a line each tenth
      const int decile = n ? done * 10 / n : 10;
      if (decile != last_decile) {
        out << line << "\n" << std::flush;
        last_decile = decile;
      }
    }
  };

  auto worker = [&]() {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= jobs.size()) return;
      Job& job = jobs[i];
      RunOptions ro;
      ro.plots = false;
      ro.log_every_ms = opt.per_run_files ? 5 : 0;
      if (opt.per_run_files) {
        ro.out_dir = opt.out_dir + "/runs/" + safeFileName(job.scenario.name);
      }
      try {
        job.entry.summary = runScenario(job.scenario, ro);
      } catch (const std::exception& e) {
        job.entry.summary.scenario = job.scenario.name;
        job.entry.summary.mode = scenario::toString(job.scenario.mode);
        job.entry.summary.outcome = "error";
        job.entry.summary.error_message = e.what();
      }
      job.entry.expectation_met = job.entry.summary.metExpectations();
      if (job.entry.expectation_met) ++as_expected;
      ++finished;
      std::lock_guard<std::mutex> lock(print_mutex);
      report();
    }
  };

  {
    std::lock_guard<std::mutex> lock(print_mutex);
    report();
  }
  const int n_threads = std::max(1, std::min<int>(opt.jobs, static_cast<int>(jobs.size())));
  std::vector<std::thread> pool;
  for (int t = 0; t < n_threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();

  std::vector<BatchEntry> entries;
  entries.reserve(jobs.size());
  for (auto& j : jobs) entries.push_back(std::move(j.entry));

  writeBatchOutputs(opt.out_dir, entries, {opt.shard_index, opt.shard_count, runs_total});
  return entries;
}

}  // namespace handover::app
