#include "app/report/run_summary.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace handover::app {
namespace {

TEST(RunSummary, JsonHasEveryContractKey) {
  RunSummary r;
  r.scenario = "demo";
  r.mode = "human_to_robot";
  r.outcome = "success";
  r.time_to_grasp = 1.25;
  r.states = {"A", "B/\"C\""};
  const std::string j = r.toJson();
  for (const char* key : {"scenario", "mode", "outcome", "success", "handovers", "aborts", "retries",
                          "time_to_grasp", "hand_still_to_grasp", "total_time", "min_human_distance",
                          "human_contacts", "object_dropped", "limit_violations", "qp_failures", "qp_relaxed",
                          "limit_guard_steps",
                          "grasp_error", "states", "control_step_us", "realtime_factor"}) {
    EXPECT_NE(j.find(std::string("\"") + key + "\":"), std::string::npos) << key;
  }
  EXPECT_NE(j.find("\"success\": true"), std::string::npos);
  EXPECT_NE(j.find("\"time_to_grasp\": 1.25"), std::string::npos);
  EXPECT_NE(j.find("\"hand_still_to_grasp\": null"), std::string::npos);
  EXPECT_NE(j.find("\"B/\\\"C\\\"\""), std::string::npos);  // quotes escaped
}

TEST(RunSummary, NonFiniteNumbersBecomeNull) {
  RunSummary r;
  r.min_human_distance = std::nan("");
  EXPECT_NE(r.toJson().find("\"min_human_distance\": null"), std::string::npos);
}

TEST(RunSummary, AnErrorNeverMeetsItsExpectations) {
  RunSummary r;
  r.outcome = "success";
  EXPECT_TRUE(r.metExpectations());
  r.expectation_failures.push_back("outcome: expected success, got timeout");
  EXPECT_FALSE(r.metExpectations());
  r.expectation_failures.clear();
  r.outcome = "error";  // e.g. the config did not load: nothing was judged
  r.error_message = "config/fsm.yaml:24: unknown key";
  EXPECT_FALSE(r.metExpectations());
}
}  // namespace
}  // namespace handover::app
