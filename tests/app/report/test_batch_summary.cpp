#include "app/report/batch_summary.hpp"

#include <gtest/gtest.h>

namespace handover::app {
namespace {

BatchEntry entry(const std::string& outcome, double ttg) {
  BatchEntry e;
  e.scenario_file = "scenes/scenarios/a,b.yaml";  // a comma must be quoted in the CSV
  e.summary.outcome = outcome;
  e.summary.time_to_grasp = ttg;
  e.summary.total_time = ttg + 1.0;
  e.summary.min_human_distance = ttg / 10.0;
  return e;
}

TEST(BatchSummary, RatesAndMeansOverSuccessesOnly) {
  const std::vector<BatchEntry> runs = {entry("success", 2.0), entry("success", 4.0), entry("hand_contact", 9.0),
                                        entry("timeout", 13.0)};
  const std::string j = batchSummaryJson(runs);
  EXPECT_NE(j.find("\"runs\": 4"), std::string::npos);
  EXPECT_NE(j.find("\"success_rate\": 0.5"), std::string::npos);
  EXPECT_NE(j.find("\"hand_contact_rate\": 0.25"), std::string::npos);
  EXPECT_NE(j.find("\"timeout_rate\": 0.25"), std::string::npos);
  EXPECT_NE(j.find("\"time_to_grasp\": 3"), std::string::npos);  // mean of 2 and 4, not of all
  EXPECT_NE(j.find("\"total_time\": 4"), std::string::npos);
  EXPECT_NE(j.find("\"min_human_distance\": 0.2"), std::string::npos);  // smallest over all runs
}

TEST(BatchSummary, CsvRowMatchesHeaderColumns) {
  const auto count = [](const std::string& s) {
    int n = 1;
    bool quoted = false;
    for (char c : s) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted) ++n;
    }
    return n;
  };
  const std::string row = resultsCsvRow(entry("success", 2.0));
  EXPECT_EQ(count(resultsCsvHeader()), count(row));
  EXPECT_EQ(row.rfind("\"scenes/scenarios/a,b.yaml\"", 0), 0u);
}

TEST(BatchSummary, EmptyBatchHasZeroRuns) {
  const std::string j = batchSummaryJson({});
  EXPECT_NE(j.find("\"runs\": 0"), std::string::npos);
  EXPECT_NE(j.find("\"min_human_distance\": null"), std::string::npos);
}

}  // namespace
}  // namespace handover::app
