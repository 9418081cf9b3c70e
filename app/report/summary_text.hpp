// A run's summary as one screen of text (what `handover run` prints).
#pragma once

#include <string>

#include "app/report/run_summary.hpp"

namespace handover::app {

/// A one-screen human-readable summary.
std::string formatSummary(const RunSummary& summary);

}  // namespace handover::app
