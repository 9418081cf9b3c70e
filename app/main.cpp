// The `handover` command line (design notes section 3). Exit codes: 0 = ran
// and expectations held, 1 = ran and an expectation failed, 2 = bad input or
// a fault before the run could start.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/hold_posture.hpp"
#include "config/input_error.hpp"

int main(int argc, char** argv) {
  using namespace handover;
  CLI::App cli{"Handover: a task-space QP controller that takes objects from and gives objects to a person"};
  cli.require_subcommand(1);

  app::HoldOptions hold;
  double max_drift_mm = 1.0;
  CLI::App* hold_cmd = cli.add_subcommand("hold", "hold the ready posture with a gravity-compensated joint PD");
  hold_cmd->add_option("--duration", hold.duration, "simulated seconds")->capture_default_str();
  hold_cmd->add_option("--urdf", hold.urdf, "robot description (default scenes/panda.urdf)");
  hold_cmd->add_option("--scene", hold.sim.scene_path, "MuJoCo scene (default scenes/handover_scene.xml)");
  hold_cmd->add_option("--max-drift-mm", max_drift_mm, "exit 1 if the TCP drifts farther")->capture_default_str();

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : 2;
  }

  try {
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
  } catch (const std::exception& e) {
    std::cerr << "handover: fault: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
