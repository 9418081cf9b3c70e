// One scenario, end to end in the simulator: each 1 ms the scripted person
// moves, the pose sensor samples it, the control cycle
// (runtime::HandoverCycle: perception, state machine, QP) turns the arm's
// state into a command for the simulator, and the judge and the log watch
// the ground truth (docs/architecture.md).
#pragma once

#include <functional>
#include <string>

#include "app/report/expectations.hpp"
#include "app/report/run_summary.hpp"
#include "app/report/summary_text.hpp"
#include "scenes/scenario/scenario.hpp"

namespace handover::app {

struct RunOptions {
  std::string out_dir;      ///< where summary.json, log.csv and plots go; "" = write nothing
  std::string video_path;   ///< MP4 to record (headless); "" = none
  bool view = false;        ///< open the interactive viewer (needs a display)
  bool plots = true;        ///< draw the PNGs after the run (needs out_dir)
  int log_every_ms = 5;     ///< log.csv row period
  double linger = 0.5;      ///< s simulated after the state machine finished
  /// Where the person's poses come from: "" = the scenario's simulated
  /// sensor; "csv:FILE" = replay a recording (docs/perception.md format);
  /// "udp:PORT" = a live tracker streaming datagrams to 127.0.0.1:PORT (the
  /// run is then paced to the wall clock). With a tracker, the simulated
  /// person's hand and arm follow the tracked poses.
  std::string tracker;
  /// Called about every 0.1 s of simulated time with (sim time, duration).
  std::function<void(double, double)> progress;
};

/// Runs the scenario. Bad input found late (a URDF, a config) throws
/// handover::InputError; faults during the run end it with outcome "error"
/// and the message in the summary.
RunSummary runScenario(const scenario::Scenario& scenario, const RunOptions& options);

}  // namespace handover::app
