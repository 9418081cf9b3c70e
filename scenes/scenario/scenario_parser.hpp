// Reads a scenario file (design notes 2) strictly: every key is checked,
// every value typed and range-checked, and the finished Scenario passes
// checkScenario(). Errors are handover::InputError "file:line: key 'a.b': ...".
// Start-up only (not real-time safe).
#pragma once

#include <string>

#include "scenes/scenario/scenario.hpp"

namespace handover::scenario {

/// Parses and validates the scenario at `path`.
Scenario parseScenario(const std::string& path);

/// Same, from text; `origin` names the file in messages and anchors relative
/// `config:` paths (its folder).
Scenario parseScenarioString(const std::string& text, const std::string& origin);

/// The controller config used when a scenario names none.
std::string defaultConfigPath();

}  // namespace handover::scenario
