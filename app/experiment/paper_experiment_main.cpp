// paper_experiment [SCENARIO] [--out DIR] [--duration S] [--only method|baseline]
//                  [--gains paper|phase|both] [--standoff M] [--execution torque|reference] [--no-plots]
// Runs the paper's reaching experiment with the method and the set-point
// baseline, with the paper's gains (config/controller.yaml) and/or the
// handover's phase gains (config/fsm.yaml params.tracking), prints their
// metrics side by side and writes DIR/<run>/ (log.csv, metrics.json, PNGs;
// <run> = method, baseline, method_phase, baseline_phase) and DIR/metrics.json (all).
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
  double standoff = 0.08;
  std::string only;
  std::string gains = "both";
  bool no_plots = false;
  std::string execution = "torque";
  cli.add_option("scenario", scenario_path, "scenario file (human_to_robot)");
  cli.add_option("--out", out_dir, "output folder");
  cli.add_option("--duration", duration, "simulated seconds (default: the scenario's duration)")->check(CLI::PositiveNumber);
  cli.add_option("--only", only, "run one controller")->check(CLI::IsMember({"method", "baseline"}));
  cli.add_option("--gains", gains,
                 "paper: config/controller.yaml's tracking gains (K = 1 / 2); phase: the handover's "
                 "approach gains (config/fsm.yaml params.tracking); both (default)")
      ->check(CLI::IsMember({"paper", "phase", "both"}));
  cli.add_option("--standoff", standoff, "pre-grasp back-off along the grasp z, m (default 0.08)")
      ->check(CLI::Range(0.0, 0.3));
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
    opt.standoff = standoff;
    if (duration > 0.0) opt.duration = duration;
    std::string json = "{\"scenario\": \"" + sc.name + "\"";
    std::vector<std::pair<std::string, app::ExperimentMetrics>> columns;
    bool unsafe = false;
    for (app::GainSet g : {app::GainSet::kPaper, app::GainSet::kHandoverPhase}) {
      if (gains != "both" && gains != app::toString(g)) continue;
      for (app::ReachController c : {app::ReachController::kMethod, app::ReachController::kBaseline}) {
        if (!only.empty() && only != app::toString(c)) continue;
        const std::string name =
            std::string(app::toString(c)) + (g == app::GainSet::kHandoverPhase ? "_phase" : "");
        opt.gains = g;
        opt.out_dir = out_dir + "/" + name;
        std::printf("running %s ...\n", name.c_str());
        std::fflush(stdout);
        const app::ExperimentRun run = app::runPaperExperiment(sc, c, opt);
        const auto& m = run.metrics;
        unsafe |= m.position_violations + m.velocity_violations + m.torque_violations + m.qp_failures > 0;
        std::printf("  K = %g / %g, %.1f s simulated in %.1f s wall -> %s\n", run.translation_stiffness,
                    run.orientation_stiffness, m.duration, run.wall_time, opt.out_dir.c_str());
        json += ", \"" + name + "\": " + app::metricsToJson(m, name);
        columns.emplace_back(name, m);
      }
    }
    json += "}\n";
    std::filesystem::create_directories(out_dir);
    std::ofstream(out_dir + "/metrics.json") << json;
    std::cout << "\n(errors against the TRUE pre-grasp frame: grasp backed off " << standoff
              << " m along its z)\n"
              << app::formatComparison(columns);
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
