// One run of a scenario file of the repository, in a scratch folder, without
// plots: the end-to-end tests' shared way to run a fixture.
#pragma once

#include <string>

#include "app/run/run_scenario.hpp"
#include "scenes/scenario/scenario_parser.hpp"
#include "tests/app/run/run_files.hpp"

namespace handover::testing {

/// Runs `repo_file` (a path relative to the source tree) with its output in
/// `dir`/out.
inline app::RunSummary runRepoFile(const ScratchDir& dir, const std::string& repo_file) {
  app::RunOptions opt;
  opt.out_dir = dir.file("out");
  opt.plots = false;
  return app::runScenario(scenario::parseScenario(repoPath(repo_file)), opt);
}

}  // namespace handover::testing
