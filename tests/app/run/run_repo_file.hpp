// One run of a scenario file of the repository, in a scratch folder, without
// plots: the end-to-end tests' shared way to run a fixture.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
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

/// How many times the run entered a state whose path ends with `suffix` ("/Grasp").
inline int stateVisits(const app::RunSummary& r, const std::string& suffix) {
  return static_cast<int>(std::count_if(r.states.begin(), r.states.end(), [&suffix](const std::string& s) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
  }));
}

/// The scenario `file` (under tests/app/run/data) succeeds entering `state`
/// once (its first attempt does it), without touching the person.
inline void expectSuccessAtTheFirstAttempt(const std::string& scratch, const std::string& file,
                                           const std::string& state) {
  const ScratchDir dir(scratch);
  const app::RunSummary r = runRepoFile(dir, "tests/app/run/data/" + file);
  EXPECT_EQ(r.outcome, "success") << file;
  EXPECT_EQ(stateVisits(r, state), 1) << file << ": the first attempt did not do it";
  EXPECT_EQ(r.human_contacts, 0) << file;
}

}  // namespace handover::testing
