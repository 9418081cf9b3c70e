// The benchmark report and the results.csv round trip it is computed from.
#include "app/report/benchmark_report.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "config/input_error.hpp"

namespace handover::app {
namespace {

BatchEntry run(int index, const std::string& direction, const std::string& grasp, const std::string& outcome,
               std::optional<double> ttg, bool met) {
  BatchEntry e;
  e.index = index;
  e.scenario_file = "gen/" + std::to_string(index) + ".yaml";
  e.category = {direction, grasp, "cylinder", "plain", "front", "right", "mid"};
  e.expected_outcome = "success";
  e.expectation_met = met;
  e.summary.scenario = e.scenario_file;
  e.summary.mode = direction == "take" ? "human_to_robot" : "robot_to_human";
  e.summary.outcome = outcome;
  e.summary.time_to_grasp = ttg;
  e.summary.hand_still_to_grasp = ttg ? std::optional<double>(*ttg - 1.0) : std::nullopt;
  e.summary.total_time = ttg ? std::optional<double>(*ttg + 3.0) : std::nullopt;
  e.summary.min_human_distance = 0.05;
  return e;
}

TEST(Percentile, NearestRank) {
  std::vector<double> v = {5, 1, 4, 2, 3};
  EXPECT_DOUBLE_EQ(percentile(v, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(percentile(v, 0.9), 5.0);
  EXPECT_DOUBLE_EQ(percentile(v, 0.0), 1.0);
  std::vector<double> none;
  EXPECT_TRUE(std::isnan(percentile(none, 0.5)));
}

TEST(GroupStats, RatesOverAllRunsTimesOverSuccesses) {
  const BatchEntry a = run(0, "take", "top", "success", 2.0, true);
  const BatchEntry b = run(1, "take", "top", "success", 4.0, true);
  const BatchEntry c = run(2, "take", "top", "timeout", 30.0, false);
  const BatchEntry d = run(3, "take", "top", "object_drop", std::nullopt, false);
  const GroupStats g = groupStats("x", {&a, &b, &c, &d});
  EXPECT_EQ(g.runs, 4);
  EXPECT_DOUBLE_EQ(g.met_rate, 0.5);
  EXPECT_DOUBLE_EQ(g.outcome_rate[0], 0.5);   // success
  EXPECT_DOUBLE_EQ(g.outcome_rate[3], 0.25);  // object_drop
  EXPECT_DOUBLE_EQ(g.outcome_rate[4], 0.25);  // timeout
  EXPECT_DOUBLE_EQ(g.time_to_grasp_median, 2.0);  // the timeout's 30 s is not a success
  EXPECT_DOUBLE_EQ(g.time_to_grasp_p90, 4.0);
  EXPECT_DOUBLE_EQ(g.total_time_median, 5.0);
}

TEST(ResultsCsv, RoundTripKeepsWhatTheReportReads) {
  std::vector<BatchEntry> runs = {run(0, "take", "side", "success", 2.5, true),
                                  run(1, "give", "top", "unsafe", std::nullopt, false)};
  runs[1].summary.error_message = "a \"quoted\", comma\nand a new line";
  runs[1].summary.limit_violations = {3, 2, 1};
  runs[1].summary.qp_failures = 7;
  runs[1].summary.qp_relaxed = 12;
  runs[1].summary.limit_guard_steps = 40;
  runs[1].summary.human_contacts = 2;
  const std::vector<BatchEntry> back = parseResultsCsv(resultsCsv(runs), "results.csv");
  ASSERT_EQ(back.size(), 2u);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_EQ(back[i].index, runs[i].index);
    EXPECT_EQ(back[i].summary.outcome, runs[i].summary.outcome);
    EXPECT_EQ(back[i].expectation_met, runs[i].expectation_met);
    EXPECT_EQ(scenario::categoryLabel(back[i].category), scenario::categoryLabel(runs[i].category));
    EXPECT_EQ(back[i].summary.time_to_grasp.has_value(), runs[i].summary.time_to_grasp.has_value());
  }
  EXPECT_DOUBLE_EQ(*back[0].summary.time_to_grasp, 2.5);
  EXPECT_EQ(back[1].summary.error_message, runs[1].summary.error_message);
  EXPECT_EQ(back[1].summary.limit_violations.velocity, 2);
  EXPECT_EQ(back[1].summary.qp_failures, 7);
  EXPECT_EQ(back[1].summary.qp_relaxed, 12);
  EXPECT_EQ(back[1].summary.limit_guard_steps, 40);
  // what is computed from the rows read back is what was computed from the runs
  EXPECT_EQ(benchmarkReportMarkdown(back, "t"), benchmarkReportMarkdown(runs, "t"));
}

TEST(ResultsCsv, BadFilesNameTheLine) {
  EXPECT_THROW(parseResultsCsv("a,b\n1,2\n", "old.csv"), InputError);
  const std::string good = resultsCsv({run(0, "take", "top", "success", 1.0, true)});
  try {
    parseResultsCsv(good + "1,2,3\n", "cut.csv");
    FAIL() << "a short row was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cut.csv:3"), std::string::npos) << e.what();
  }
}

TEST(BenchmarkReport, TablesPerCategory) {
  const std::vector<BatchEntry> runs = {run(0, "take", "side", "success", 2.0, true),
                                        run(1, "take", "side", "timeout", std::nullopt, false),
                                        run(2, "give", "top", "success", 3.0, true)};
  const std::string md = benchmarkReportMarkdown(runs, "Bench");
  EXPECT_EQ(md.rfind("# Bench", 0), 0u);
  EXPECT_NE(md.find("| all | 3 | 66.7 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| take | 2 | 50.0 | 50.0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| give | 1 | 100.0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| take/side/cylinder | 2 |"), std::string::npos) << md;
  EXPECT_NE(md.find("## By grasp family"), std::string::npos);
}

TEST(BenchmarkComparison, MarksCategoriesThatGotWorse) {
  const std::vector<BatchEntry> before = {run(0, "take", "side", "success", 2.0, true),
                                          run(1, "take", "side", "success", 2.0, true),
                                          run(2, "give", "top", "timeout", std::nullopt, false)};
  const std::vector<BatchEntry> after = {run(0, "take", "side", "success", 2.0, true),
                                         run(1, "take", "side", "timeout", std::nullopt, false),
                                         run(2, "give", "top", "success", 3.0, true)};
  const std::string md = benchmarkComparisonMarkdown(before, after, "a", "b");
  EXPECT_NE(md.find("| all | 3 | 66.7 | 3 | 66.7 | +0.0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| take | 2 | 100.0 | 2 | 50.0 | -50.0 **worse** |"), std::string::npos) << md;
  EXPECT_NE(md.find("| give | 1 | 0.0 | 1 | 100.0 | +100.0 |"), std::string::npos) << md;
  // a group only one batch has
  const std::string only = benchmarkComparisonMarkdown(before, {run(0, "take", "around_axis", "success", 1.0, true)}, "a", "b");
  EXPECT_NE(only.find("| around_axis | - | - | 1 | 100.0 | - |"), std::string::npos) << only;
}

}  // namespace
}  // namespace handover::app
