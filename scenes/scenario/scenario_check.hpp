// Semantic checks of a Scenario that need more than one key: mode
// consistency, the script's hold/release sequence, and that every hand target
// (start, reach, withdraw, pull end) lies within the person's arm reach from
// the shoulder (body_dimensions.hpp). Throws handover::InputError naming the
// file, the dotted key and the line. Start-up only.
#pragma once

#include "scenes/scenario/scenario.hpp"

namespace handover::scenario {

/// Throws InputError on the first problem found.
void checkScenario(const Scenario& s);

/// Throws InputError "file:line: key 'k': message" for a stored location.
[[noreturn]] void failAt(const SourceRef& where, const std::string& message);

}  // namespace handover::scenario
