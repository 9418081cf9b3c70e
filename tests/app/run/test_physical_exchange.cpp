// The physical exchange end to end in the simulator (issue 13): a 1 kg
// object handed to the robot does not sink when the person lets go, and a
// 1 kg object given to a person is held still while the receiver pulls and
// let go only then. Measured from the run's own log.csv as
// scripts/exchange_sink.py does (docs/method.md, "The physical exchange");
// and a fast pull from the benchmark is answered within 2 cm.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "app/run/run_scenario.hpp"
#include "scenes/scenario/scenario_parser.hpp"
#include "tests/app/run/run_files.hpp"
#include "tests/app/run/run_repo_file.hpp"

namespace handover {
namespace {

using testing::CsvTable;
using testing::ScratchDir;

Eigen::Vector3d point(const CsvTable& t, std::size_t row, const std::string& prefix) {
  return {t.number(row, prefix + "x"), t.number(row, prefix + "y"), t.number(row, prefix + "z")};
}

/// Runs the shipped scenario `name` with the object's mass set to `mass`.
app::RunSummary runWithMass(const ScratchDir& dir, const std::string& name, double mass, CsvTable& log) {
  std::string text = testing::readText(testing::repoPath("scenes/scenarios/" + name + ".yaml"));
  const auto at = text.find("mass: 0.3");
  if (at == std::string::npos) throw std::runtime_error(name + ": no 'mass: 0.3' line to change");
  text.replace(at, 9, "mass: " + std::to_string(mass));
  const std::string copy = dir.file(name + ".yaml");
  testing::writeText(copy, text);
  app::RunOptions opt;
  opt.out_dir = dir.file("out");
  opt.plots = false;
  const app::RunSummary s = app::runScenario(scenario::parseScenario(copy), opt);
  log = testing::readCsv(opt.out_dir + "/log.csv");
  return s;
}

/// How far the TCP moved from the pull's onset (the hand, at rest while the
/// robot waits for the pull, moves 2 mm) until the fingers opened past the
/// object, m; `felt`: the pull began before the fingers opened.
struct PullMeasure {
  double moved = 0.0;
  bool felt = false;
};

PullMeasure measurePull(const app::RunSummary& s, const CsvTable& log) {
  const auto& states = s.states;
  const auto pull = std::find_if(states.begin(), states.end(),
                                 [](const std::string& p) { return p.find("DetectPull") != std::string::npos; });
  const auto release = std::find_if(states.begin(), states.end(),
                                    [](const std::string& p) { return p.find("/Release") != std::string::npos; });
  if (pull == states.end() || release == states.end()) throw std::runtime_error("no DetectPull and Release");
  if (pull - states.begin() > release - states.begin()) throw std::runtime_error("released before a pull");
  std::size_t start = 0;
  while (start < log.rows.size() && log.rows[start][1].find("DetectPull") == std::string::npos) ++start;
  if (start == log.rows.size()) throw std::runtime_error("no DetectPull in log.csv");
  std::size_t onset = start;
  while (onset < log.rows.size() && (point(log, onset, "hand_") - point(log, start, "hand_")).norm() <= 0.002)
    ++onset;
  if (onset == log.rows.size()) throw std::runtime_error("the receiver never pulled");
  const double width0 = log.number(start, "finger_width");
  PullMeasure m;
  std::size_t r = onset;  // up to the first sample with the fingers opened past the object, inclusive
  for (; r < log.rows.size(); ++r) {
    m.moved = std::max(m.moved, (point(log, r, "tcp_") - point(log, onset, "tcp_")).norm());
    if (log.number(r, "finger_width") > width0 + 0.005) break;
  }
  if (r == log.rows.size()) throw std::runtime_error("the fingers never opened");
  m.felt = r > onset + 1;
  return m;
}

TEST(PhysicalExchange, OneKilogramDoesNotSinkWhenThePersonLetsGo) {
  ScratchDir dir("exchange_release");
  CsvTable log;
  const app::RunSummary s = runWithMass(dir, "default", 1.0, log);
  EXPECT_EQ(s.outcome, "success");
  ASSERT_GT(log.rows.size(), 100u);
  // the fingers close, then the person's hand moves 1 cm relative to the object: the release
  std::size_t close = 0;
  while (close < log.rows.size() && log.number(close, "gripper_cmd") > 0.04) ++close;
  ASSERT_LT(close, log.rows.size()) << "the fingers never closed";
  const Eigen::Vector3d rel0 = point(log, close, "hand_") - point(log, close, "object_");
  std::size_t release = close;
  while (release < log.rows.size() &&
         (point(log, release, "hand_") - point(log, release, "object_") - rel0).norm() <= 0.01)
    ++release;
  ASSERT_LT(release, log.rows.size()) << "the person never let go";
  const double t0 = log.number(release, "time"), z0 = log.number(release, "object_z");
  double sink = 0.0, share = 0.0;
  for (std::size_t r = release; r < log.rows.size() && log.number(r, "time") <= t0 + 1.0; ++r) {
    sink = std::max(sink, z0 - log.number(r, "object_z"));
    share = std::max(share, log.number(r, "load_share"));
  }
  EXPECT_LE(sink, 0.010) << "the object sank by " << sink << " m in the second after the release";
  EXPECT_GT(share, 0.9) << "the robot never carried the weight";
  // while the person still held it the robot carried little of it
  EXPECT_LT(log.number(close, "load_share"), 0.5);
}

TEST(PhysicalExchange, OneKilogramIsHeldStillWhileTheReceiverPulls) {
  ScratchDir dir("exchange_pull");
  CsvTable log;
  const app::RunSummary s = runWithMass(dir, "r2h_basic", 1.0, log);
  EXPECT_EQ(s.outcome, "success");
  const PullMeasure m = measurePull(s, log);
  EXPECT_LE(m.moved, 0.02) << "the TCP moved " << m.moved << " m during the pull";
  // the pull is felt (the arm is not a wall) when it began before the fingers
  // opened; a receiver who takes the object's weight in the palm is released
  // to before moving at all
  if (m.felt) EXPECT_GT(m.moved, 0.0);
}

// A fast pull from the benchmark (tests/app/run/data/r2h_fast_pull.yaml:
// 14.6 cm in 0.4 s, 0.7 m/s at its peak). The scripted hand moves as
// scripted whatever the arm does, so the TCP goes with it until the fingers
// open: the pull must be told within about a centimetre. Read through a
// second, slower filter (the estimator's 10 ms, then 50 ms) it was told
// 15 mm in and the TCP had moved 21.5 mm when the fingers let go. Since
// 2026-11-28 (the presentation settles 0.4 s sooner) the robot waits for the
// pull before the receiver closes their hand, and the jolt of their grasp,
// with their hand at the object, already reads as the pull: the fingers open
// before the hand moves (0 mm). Either way the TCP must not be dragged.
TEST(PhysicalExchange, AFastPullIsAnsweredWithinTwoCentimetres) {
  ScratchDir dir("exchange_fast_pull");
  app::RunOptions opt;
  opt.out_dir = dir.file("out");
  opt.plots = false;
  const app::RunSummary s =
      app::runScenario(scenario::parseScenario(testing::repoPath("tests/app/run/data/r2h_fast_pull.yaml")), opt);
  const CsvTable log = testing::readCsv(opt.out_dir + "/log.csv");
  EXPECT_EQ(s.outcome, "success");
  const PullMeasure m = measurePull(s, log);
  EXPECT_LE(m.moved, 0.02) << "the TCP moved " << m.moved << " m during the pull";
}

// A person who withdraws as the fingers close on the object (h2r_taken_back,
// a retry from the benchmark withdrawing 0.8 s after the reach) takes it
// back: the fingers let go and the robot tries again when they return. Held
// on to, the arm was dragged after them (190 velocity- and 62 position-limit
// steps).
TEST(PhysicalExchange, APersonWhoTakesTheObjectBackIsNotDraggedAfter) {
  testing::ScratchDir dir("taken_back");
  const app::RunSummary s = testing::runRepoFile(dir, "tests/app/run/data/h2r_taken_back.yaml");
  EXPECT_EQ(s.limit_violations.velocity, 0) << app::formatSummary(s);
  EXPECT_EQ(s.limit_violations.position, 0);
  EXPECT_EQ(s.human_contacts, 0);
  EXPECT_EQ(s.outcome, "success") << app::formatSummary(s);
  EXPECT_GE(s.retries, 1);  // let go, then taken when they came back
}

}  // namespace
}  // namespace handover
