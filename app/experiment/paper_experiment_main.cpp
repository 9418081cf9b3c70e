// paper_experiment [SCENARIO] [--out DIR] [--duration S] [--only method|baseline] [--no-plots]
// Runs the paper's reaching experiment with the method and the set-point
// baseline, prints their metrics side by side and writes DIR/method/,
// DIR/baseline/ (log.csv, metrics.json, PNGs) and DIR/metrics.json (both).
// Exit codes: 0 ran, 1 a limit was violated or the QP failed, 2 bad input.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "app/experiment/paper_experiment.hpp"
#include "config/input_error.hpp"
#include "scenes/scenario/scenario_parser.hpp"

int main(int argc, char** argv) {
  using namespace handover;
  CLI::App cli{"The paper's handover reaching experiment: method vs set-point baseline"};
  std::string scenario_path = std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios/paper/paper_experiment.yaml";
  std::string out_dir = "out/paper_experiment";
  double duration = 0.0;
  std::string only;
  bool no_plots = false;
  std::string execution = "torque";
  cli.add_option("scenario", scenario_path, "scenario file (human_to_robot)");
  cli.add_option("--out", out_dir, "output folder");
  cli.add_option("--duration", duration, "simulated seconds (default: the scenario's duration)")->check(CLI::PositiveNumber);
  cli.add_option("--only", only, "run one controller")->check(CLI::IsMember({"method", "baseline"}));
  cli.add_option("--execution", execution,
                 "reference: the arm tracks the QP's integrated joint state (as mc_rtc on a Panda); "
                 "torque: inverse-dynamics torques on the measured state")
      ->check(CLI::IsMember({"reference", "torque"}));
  cli.add_flag("--no-plots", no_plots, "skip the PNGs");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e) == 0 ? 0 : 2;
  }

  try {
    const scenario::Scenario sc = scenario::parseScenario(scenario_path);
    app::ExperimentOptions opt;
    opt.plots = !no_plots;
    opt.execution = app::parseExecution(execution);
    if (duration > 0.0) opt.duration = duration;
    std::string json = "{\"scenario\": \"" + sc.name + "\"";
    app::ExperimentMetrics results[2];
    bool ran[2] = {false, false};
    bool unsafe = false;
    for (app::ReachController c : {app::ReachController::kMethod, app::ReachController::kBaseline}) {
      if (!only.empty() && only != app::toString(c)) continue;
      opt.out_dir = out_dir + "/" + app::toString(c);
      std::printf("running %s ...\n", app::toString(c));
      std::fflush(stdout);
      const app::ExperimentRun run = app::runPaperExperiment(sc, c, opt);
      const int i = c == app::ReachController::kMethod ? 0 : 1;
      results[i] = run.metrics;
      ran[i] = true;
      const auto& m = run.metrics;
      unsafe |= m.position_violations + m.velocity_violations + m.torque_violations + m.qp_failures > 0;
      std::printf("  %.1f s simulated in %.1f s wall -> %s\n", m.duration, run.wall_time, opt.out_dir.c_str());
      json += std::string(", \"") + app::toString(c) + "\": " + app::metricsToJson(m, app::toString(c));
    }
    json += "}\n";
    std::filesystem::create_directories(out_dir);
    std::ofstream(out_dir + "/metrics.json") << json;
    if (ran[0] && ran[1]) {
      std::cout << "\n" << app::formatComparison(results[0], results[1]);
    } else {
      const app::ExperimentMetrics& m = ran[0] ? results[0] : results[1];
      std::cout << "\n" << app::formatComparison(m, m) << "(only " << only << " ran: both columns are it)\n";
    }
    std::printf("\nmetrics: %s/metrics.json\n", out_dir.c_str());
    return unsafe ? 1 : 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
