// A scenario's `expect:` lines checked against a run's summary.
#pragma once

#include <string>
#include <vector>

#include "app/report/run_summary.hpp"
#include "scenes/scenario/scenario.hpp"

namespace handover::app {

/// The `expect:` lines of the scenario that the summary does not meet, as
/// readable sentences ("outcome: expected success, got timeout").
std::vector<std::string> checkExpectations(const scenario::Scenario& scenario, const RunSummary& summary);

}  // namespace handover::app
