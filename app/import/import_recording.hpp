// `handover import`: a recording mapping (docs/recordings.md) and its data
// in, our tracker CSV out (docs/perception.md), plus the scenario lines that
// put the simulated person and object where the recording starts.
#pragma once

#include <optional>
#include <string>

namespace handover::app {

struct ImportOptions {
  std::string mapping;             ///< mapping file (YAML)
  std::string data_dir;            ///< data folder, "" = the mapping's `data`
  std::string out;                 ///< tracker CSV to write
  std::optional<double> speed;     ///< overrides the mapping's speed
  std::optional<bool> mirror;      ///< overrides the mapping's mirror
};

/// Converts and writes the CSV; returns a short report: samples, duration,
/// where the hand and object start and end, and scenario lines (human.start,
/// human.holds_object, human.hand) that match the first sample. Throws
/// InputError on bad input.
std::string importRecordingToCsv(const ImportOptions& options);

}  // namespace handover::app
