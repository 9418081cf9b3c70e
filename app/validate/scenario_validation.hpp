// The one validation of a scenario, shared by `handover check` and `handover
// run` (and every run of a batch), so that check accepts nothing run refuses.
// Beyond the parser's checks (scenes/scenario/scenario_parser.hpp):
// - the controller config the scenario names, read with each `set:` override
//   applied in turn; an override that breaks a bound is reported at the
//   scenario's line;
// - the control period equals the simulator's step (the run steps both once
//   per millisecond);
// - start_q keeps the robot clear of the table, itself and the person as
//   placed at t = 0;
// - the scaled torque limits hold the arm (and the object it carries) against
//   gravity at the start and posture configurations with 20% to spare.
// Throws handover::InputError naming the file, key and line. Start-up only.
#pragma once

#include <string>

#include "control/controller_config.hpp"
#include "scenes/scenario/scenario.hpp"

namespace handover::app {

/// The simulator's step (scenes/handover_scene.xml <option timestep>), s.
constexpr double kSceneTimestep = 0.001;

/// The controller config of `sc` (its file with `set:` applied), validated.
control::ControllerConfig controllerConfigOf(const scenario::Scenario& sc);

/// Everything above; throws on the first problem.
void validateScenario(const scenario::Scenario& sc);

/// parseScenario(path) followed by validateScenario.
scenario::Scenario loadValidScenario(const std::string& path);

}  // namespace handover::app
