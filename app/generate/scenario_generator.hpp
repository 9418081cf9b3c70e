// `handover generate`: benchmark scenarios drawn from the space of ordinary
// handovers (docs/benchmark.md documents the distribution). A draw is a
// pure function of (seed, index, mode): the same seed gives the same files,
// and file k does not depend on how many files are asked for. Every file is
// checked with the same validation as `handover check` (parser, bounds,
// the model-based checks); a draw that
// fails it (a target the person cannot reach, ...) is drawn again.
// Start-up / tooling only (not real-time safe).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace handover::app {

enum class GenerateMode { Take, Give, Both };

struct GenerateOptions {
  int count = 100;              ///< files to write
  std::uint64_t seed = 1;       ///< benchmark seed
  std::string out_dir;          ///< folder (created if missing)
  GenerateMode mode = GenerateMode::Both;
};

struct GeneratedScenario {
  std::string name;  ///< also the file name without ".yaml"
  std::string yaml;  ///< the file's text (valid: parses and passes the scenario checks)
  int draws = 0;     ///< attempts it took (1 = the first draw was valid)
};

/// Scenario `index` (>= 0) of the benchmark with `seed`. Throws
/// std::runtime_error if no valid draw was found (does not happen with the
/// shipped distribution; the limit guards a broken change).
GeneratedScenario generateScenario(std::uint64_t seed, int index, GenerateMode mode);

/// Writes options.count files into options.out_dir; returns their paths in
/// index order. Throws OutputError (app/report/output_files.hpp) naming the
/// folder or file when it cannot be written.
std::vector<std::string> generateScenarios(const GenerateOptions& options);

/// "take" | "give" | "both" -> mode; throws std::invalid_argument otherwise.
GenerateMode parseGenerateMode(const std::string& word);

}  // namespace handover::app
