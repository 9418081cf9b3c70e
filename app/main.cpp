// The `handover` command line (design notes section 3). Exit codes: 0 = ran
// and expectations held, 1 = ran and an expectation failed, 2 = bad input or
// a fault before the run could start.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <unistd.h>

#include "app/batch/batch_outputs.hpp"
#include "app/batch/batch_runner.hpp"
#include "app/generate/scenario_generator.hpp"
#include "app/hold_posture.hpp"
#include "app/import/import_recording.hpp"
#include "app/plot_runner.hpp"
#include "app/report/benchmark_report.hpp"
#include "app/report/output_files.hpp"
#include "app/run/run_scenario.hpp"
#include "app/validate/scenario_validation.hpp"
#include "config/config_directory.hpp"
#include "config/input_error.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace {

using namespace handover;

int runCommand(const std::string& file, std::string out_dir, const std::string& video, bool view, bool quiet,
               int log_every_ms, const std::string& tracker) {
  const scenario::Scenario sc = scenario::parseScenario(file);
  if (out_dir.empty()) out_dir = "out/" + app::safeFileName(sc.name);
  app::RunOptions ro;
  ro.out_dir = out_dir;
  ro.video_path = video;
  ro.view = view;
  ro.log_every_ms = log_every_ms;
  ro.tracker = tracker;
  if (!quiet && isatty(STDERR_FILENO)) {
    ro.progress = [](double t, double duration) {
      std::fprintf(stderr, "\rsimulating %5.1f / %.1f s", t, duration);
    };
  }
  const app::RunSummary r = app::runScenario(sc, ro);
  if (ro.progress) std::fprintf(stderr, "\r%40s\r", "");
  int plot_status = 0;
  if (log_every_ms > 0) plot_status = app::drawPlots(out_dir, quiet);
  std::cout << app::formatSummary(r);
  std::cout << "files      " << out_dir << "/summary.json" << (log_every_ms > 0 ? ", log.csv" : "")
            << (log_every_ms > 0 && plot_status == 0 ? ", *.png" : "") << (video.empty() ? "" : ", " + video) << "\n";
  if (plot_status != 0) std::cerr << "handover: warning: plots not drawn (exit " << plot_status << ")\n";
  const int code = app::runExitCode(r, sc.expect.outcome.has_value());
  if (code == 1 && r.expectation_failures.empty()) {
    if (r.outcome == "no_perception")
      std::cout << "BLIND      the person could not be seen (no `expect: outcome` accepts it): exit 1\n";
    else
      std::cout << "UNSAFE     a limit was violated or the QP failed (no `expect: outcome` accepts it): exit 1\n";
  }
  return code;
}

int batchCommand(const app::BatchOptions& opt, bool quiet) {
  const std::vector<app::BatchEntry> entries = app::runBatch(opt, std::cerr);
  int failed = 0, errors = 0;
  std::map<std::string, int> outcomes;
  for (const auto& e : entries) {
    ++outcomes[e.summary.outcome];
    failed += e.summary.expectation_failures.empty() ? 0 : 1;
    errors += e.summary.outcome == "error" ? 1 : 0;
    if (!quiet && !e.summary.expectation_failures.empty()) {
      std::cout << e.summary.scenario << ": " << e.summary.expectation_failures.front() << "\n";
    }
    if (!e.summary.error_message.empty()) std::cerr << e.summary.scenario << ": error: " << e.summary.error_message << "\n";
  }
  std::cout << entries.size() << " runs:";
  for (const auto& [o, n] : outcomes) std::cout << " " << o << " " << n;
  std::cout << "; " << failed << " with unmet expectations\n";
  const int plot_status = app::drawReportPlot(opt.out_dir, true);
  std::cout << "files      " << opt.out_dir << "/results.csv, summary.json, report.md"
            << (plot_status == 0 ? ", report.png" : "") << "\n";
  if (plot_status != 0) std::cerr << "handover: warning: report.png not drawn (exit " << plot_status << ")\n";
  if (errors) return 2;
  return failed ? 1 : 0;
}

int checkCommand(const std::vector<std::string>& files) {
  int bad = 0;
  for (const auto& f : files) {
    try {
      const scenario::Scenario sc = app::loadValidScenario(f);
      std::cout << f << ": ok (" << sc.name << ", " << scenario::toString(sc.mode) << ", " << sc.human.script.size()
                << " steps)\n";
    } catch (const InputError& e) {
      std::cerr << e.what() << "\n";
      ++bad;
    } catch (const std::exception& e) {
      std::cerr << f << ": fault: " << e.what() << "\n";
      ++bad;
    }
  }
  return bad ? 2 : 0;
}

// "K/N" with 1 <= K <= N
bool parseShard(const std::string& text, int& k, int& n) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return false;
  try {
    std::size_t used_k = 0, used_n = 0;
    k = std::stoi(text.substr(0, slash), &used_k);
    n = std::stoi(text.substr(slash + 1), &used_n);
    if (used_k != slash || used_n != text.size() - slash - 1) return false;
  } catch (const std::exception&) {
    return false;
  }
  return n >= 1 && k >= 1 && k <= n;
}

int generateCommand(const app::GenerateOptions& opt) {
  const std::vector<std::string> paths = app::generateScenarios(opt);
  std::cout << paths.size() << " scenarios written to " << opt.out_dir << " (seed " << opt.seed << ")\n";
  return 0;
}

int reportCommand(const std::string& dir) {
  app::rewriteReport(dir);
  const int plot_status = app::drawReportPlot(dir, true);
  std::cout << "files      " << dir << "/report.md" << (plot_status == 0 ? ", report.png" : "") << "\n";
  if (plot_status != 0) std::cerr << "handover: warning: report.png not drawn (exit " << plot_status << ")\n";
  return 0;
}

int compareCommand(const std::string& before, const std::string& after, const std::string& out) {
  const std::string md = app::benchmarkComparisonMarkdown(app::readBatchResults(before), app::readBatchResults(after),
                                                          before, after);
  std::cout << md;
  if (!out.empty()) {
    std::ofstream f(out);
    f << md;
    f.close();
    if (!f) throw std::runtime_error(out + ": cannot write");
  }
  return 0;
}

int mergeCommand(const std::vector<std::string>& dirs, const std::string& out) {
  app::mergeBatches(dirs, out);
  const int plot_status = app::drawReportPlot(out, true);
  std::cout << "merged " << dirs.size() << " shards\nfiles      " << out << "/results.csv, summary.json, report.md"
            << (plot_status == 0 ? ", report.png" : "") << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"Handover: a task-space QP controller that takes objects from and gives objects to a person"};
  cli.require_subcommand(1);
  std::string config_dir;
  cli.add_option("--config-dir", config_dir,
                 "read the configuration (controller.yaml, fsm.yaml, ...) from this folder instead of the "
                 "source tree's config/: a tuned copy, compared without rebuilding");

  // run
  std::string run_file, run_out, run_video, run_tracker;
  bool run_view = false, run_quiet = false;
  int log_every = 5;
  CLI::App* run_cmd = cli.add_subcommand("run", "run one scenario in the simulator");
  run_cmd->add_option("scenario", run_file, "scenario file (YAML)")->required();
  run_cmd->add_option("--out", run_out, "output folder (default out/<scenario name>)");
  run_cmd->add_option("--video", run_video, "record an MP4 (headless)");
  run_cmd->add_flag("--view", run_view, "open the interactive viewer (needs a display)");
  run_cmd->add_flag("--quiet", run_quiet, "no progress, no plot messages");
  run_cmd->add_option("--tracker", run_tracker,
                      "person poses from csv:FILE (replay) or udp:PORT (live, paced to the wall clock) "
                      "instead of the simulated sensor");
  run_cmd->add_option("--log-every", log_every, "log.csv row period in ms (0 = no log, no plots)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));

  // batch
  app::BatchOptions batch;
  bool batch_quiet = false;
  CLI::App* batch_cmd = cli.add_subcommand("batch", "run many scenarios in parallel");
  batch_cmd->add_option("scenarios", batch.files, "scenario files")->required();
  batch_cmd->add_option("--jobs,-j", batch.jobs, "parallel runs")->capture_default_str()->check(CLI::Range(1, 64));
  batch_cmd->add_option("--out", batch.out_dir, "output folder")->capture_default_str();
  batch_cmd->add_option("--vary", batch.vary, "randomized variants of each scenario (reproducible seeds)")
      ->check(CLI::Range(0, 100000));
  batch_cmd->add_flag("--runs", batch.per_run_files, "also write each run's summary.json and log.csv");
  batch_cmd->add_flag("--quiet", batch_quiet, "no progress bar");
  std::string batch_shard;
  batch_cmd->add_option("--shard", batch_shard,
                        "K/N: run only the K-th of N disjoint slices (run i belongs to slice i mod N + 1); "
                        "combine the slices with `handover merge`");

  // generate
  app::GenerateOptions gen;
  std::string gen_mode = "both";
  CLI::App* gen_cmd = cli.add_subcommand("generate", "write benchmark scenarios drawn from docs/benchmark.md's distribution");
  gen_cmd->add_option("--count", gen.count, "number of files")->required()->check(CLI::Range(1, 1000000));
  gen_cmd->add_option("--seed", gen.seed, "benchmark seed (the same seed gives the same files)")->capture_default_str();
  gen_cmd->add_option("--out", gen.out_dir, "output folder")->required();
  gen_cmd->add_option("--mode", gen_mode, "take (human to robot), give (robot to human) or both")
      ->capture_default_str()
      ->check(CLI::IsMember({"take", "give", "both"}));

  // report
  std::string report_dir;
  CLI::App* report_cmd = cli.add_subcommand("report", "write report.md and report.png of a batch from DIR/results.csv");
  report_cmd->add_option("dir", report_dir, "a batch's output folder")->required();

  // compare
  std::string compare_before, compare_after, compare_out;
  CLI::App* compare_cmd = cli.add_subcommand("compare", "ok % per category of two batches, before and after a change");
  compare_cmd->add_option("before", compare_before, "a batch's output folder (the reference)")->required();
  compare_cmd->add_option("after", compare_after, "a batch's output folder (the change)")->required();
  compare_cmd->add_option("--out", compare_out, "also write the table to this file (markdown)");

  // merge
  std::vector<std::string> merge_dirs;
  std::string merge_out;
  CLI::App* merge_cmd = cli.add_subcommand("merge", "combine the output folders of `batch --shard K/N` runs into one");
  merge_cmd->add_option("dirs", merge_dirs, "the shards' output folders")->required();
  merge_cmd->add_option("--out", merge_out, "output folder")->required();

  // check
  std::vector<std::string> check_files;
  CLI::App* check_cmd = cli.add_subcommand("check", "validate scenario files without running them");
  check_cmd->add_option("scenarios", check_files, "scenario files")->required();

  // import
  app::ImportOptions imp;
  double imp_speed = 0.0;
  bool imp_mirror = false;
  CLI::App* import_cmd = cli.add_subcommand("import", "turn a recording (described by a mapping, docs/recordings.md) "
                                                      "into a tracker CSV for `run --tracker csv:FILE`");
  import_cmd->add_option("mapping", imp.mapping, "recording mapping (YAML)")->required();
  import_cmd->add_option("--data", imp.data_dir, "folder of the recording's files (default: the mapping's `data`)");
  import_cmd->add_option("--out", imp.out, "tracker CSV to write")->required();
  import_cmd->add_option("--speed", imp_speed, "playback speed, overrides the mapping's (e.g. 0.8, 1.2)")
      ->check(CLI::PositiveNumber);
  import_cmd->add_flag("--mirror", imp_mirror, "swap left and right (a right hand's motion becomes a left hand's)");

  // plot
  std::string plot_dir;
  CLI::App* plot_cmd = cli.add_subcommand("plot", "redraw the plots of a run from DIR/log.csv");
  plot_cmd->add_option("dir", plot_dir, "a run's output folder")->required();

  // hold (the smallest loop: the handover cycle with config/fsm_hold.yaml, joint PD on the driver side)
  app::HoldOptions hold;
  double max_drift_mm = 1.0;
  CLI::App* hold_cmd = cli.add_subcommand("hold", "hold the ready posture: the handover cycle (our model's gravity) and a joint PD");
  hold_cmd->add_option("--duration", hold.duration, "simulated seconds")->capture_default_str();
  hold_cmd->add_option("--urdf", hold.urdf, "robot description (default scenes/panda.urdf)");
  hold_cmd->add_option("--scene", hold.sim.scene_path, "MuJoCo scene (default scenes/handover_scene.xml)");
  hold_cmd->add_option("--max-drift-mm", max_drift_mm, "exit 1 if the TCP drifts farther")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](std::string& text) {
            // CLI::Range lets nan through (every comparison with it is false)
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            return std::isfinite(v) && v >= 0.0 && end && *end == '\0' ? std::string()
                                                                        : "expected a finite number >= 0, got " + text;
          },
          "MM >= 0"));

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : 2;
  }

  try {
    if (!config_dir.empty()) setConfigDirectory(config_dir);
    if (run_cmd->parsed()) return runCommand(run_file, run_out, run_video, run_view, run_quiet, log_every, run_tracker);
    if (batch_cmd->parsed()) {
      batch.progress = !batch_quiet;
      if (!batch_shard.empty() && !parseShard(batch_shard, batch.shard_index, batch.shard_count)) {
        std::cerr << "handover: error: --shard '" << batch_shard << "': expected K/N with 1 <= K <= N (e.g. 2/8)\n";
        return 2;
      }
      return batchCommand(batch, batch_quiet);
    }
    if (check_cmd->parsed()) return checkCommand(check_files);
    if (import_cmd->parsed()) {
      if (imp_speed > 0.0) imp.speed = imp_speed;
      if (imp_mirror) imp.mirror = true;
      std::cout << app::importRecordingToCsv(imp) << "files      " << imp.out << "\n";
      return 0;
    }
    if (gen_cmd->parsed()) {
      gen.mode = app::parseGenerateMode(gen_mode);
      return generateCommand(gen);
    }
    if (report_cmd->parsed()) return reportCommand(report_dir);
    if (merge_cmd->parsed()) return mergeCommand(merge_dirs, merge_out);
    if (compare_cmd->parsed()) return compareCommand(compare_before, compare_after, compare_out);
    if (plot_cmd->parsed()) {
      if (!std::filesystem::exists(plot_dir + "/log.csv")) {
        std::cerr << "handover: error: " << plot_dir << "/log.csv: no such file (run `handover run` first)\n";
        return 2;
      }
      const int status = app::drawPlots(plot_dir, false);
      if (status != 0) std::cerr << "handover: error: plots of " << plot_dir << " not drawn (exit " << status << ")\n";
      return status == 0 ? 0 : 2;
    }
    if (hold_cmd->parsed()) {
      const app::HoldSummary s = app::holdPosture(hold);
      app::printHoldSummary(std::cout, s);
      if (s.max_tcp_drift * 1e3 > max_drift_mm) {
        std::cout << "hold: FAILED, TCP drift above " << max_drift_mm << " mm\n";
        return 1;
      }
    }
  } catch (const InputError& e) {
    std::cerr << "handover: error: " << e.what() << "\n";
    return 2;
  } catch (const app::OutputError& e) {
    std::cerr << "handover: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "handover: fault: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
