// Behaviour is pinned: a shipped scenario run today gives the log.csv of the
// committed reference run (tests/app/run/data/reference_<name>.csv: every
// 20th row, a few columns, cut by scripts/make_reference_log.py from a run
// of the code before the cycle was restructured). States must match
// exactly; numbers to the log's rounding (6 significant digits), with a
// little room for a platform's last-bit differences.
// Regenerate a reference only when behaviour changes on purpose.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app/run/run_scenario.hpp"
#include "scenes/scenario/scenario_parser.hpp"
#include "tests/app/run/run_files.hpp"

namespace handover {
namespace {

constexpr std::size_t kEvery = 20;  // as scripts/make_reference_log.py
constexpr double kTolerance = 1e-4;  // relative to max(1, |reference|)

void compareWithReference(const std::string& name) {
  testing::ScratchDir dir("reference_" + name);
  const scenario::Scenario sc = scenario::parseScenario(testing::repoPath("scenes/scenarios/" + name + ".yaml"));
  app::RunOptions opt;
  opt.out_dir = dir.path();
  opt.plots = false;
  app::runScenario(sc, opt);

  const testing::CsvTable ref = testing::readCsv(testing::repoPath("tests/app/run/data/reference_" + name + ".csv"));
  const testing::CsvTable now = testing::readCsv(dir.file("log.csv"));
  ASSERT_GE(ref.rows.size(), 10u);
  ASSERT_EQ(now.rows.size() / kEvery + (now.rows.size() % kEvery ? 1 : 0), ref.rows.size())
      << "the run has " << now.rows.size() << " log rows";
  int compared = 0;
  for (std::size_t r = 0; r < ref.rows.size(); ++r) {
    const std::size_t row = r * kEvery;
    for (std::size_t c = 0; c < ref.header.size(); ++c) {
      const std::string& col = ref.header[c];
      const int k = now.column(col);
      ASSERT_GE(k, 0) << "log.csv has no column " << col;
      const std::string& got = now.rows[row].at(static_cast<std::size_t>(k));
      const std::string& want = ref.rows[r].at(c);
      if (col == "state") {
        EXPECT_EQ(got, want) << "row " << row;
        continue;
      }
      const double a = std::strtod(got.c_str(), nullptr), b = std::strtod(want.c_str(), nullptr);
      EXPECT_LE(std::abs(a - b), kTolerance * std::max(1.0, std::abs(b)))
          << col << " at t = " << ref.rows[r][0] << ": " << got << " vs reference " << want;
      ++compared;
    }
  }
  EXPECT_GT(compared, 500);
}

TEST(ReferenceRun, HumanToRobotDefaultScenario) { compareWithReference("default"); }
TEST(ReferenceRun, RobotToHumanBasic) { compareWithReference("r2h_basic"); }

}  // namespace
}  // namespace handover
