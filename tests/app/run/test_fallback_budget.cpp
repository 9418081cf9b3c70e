// The fallback budget (app/run/fallback_budget.hpp): a run stops once the QP
// failed in more than max_share of the steps of the last window, not before,
// and sporadic failures never stop it.
#include <gtest/gtest.h>

#include "app/run/fallback_budget.hpp"

using handover::app::FallbackBudget;

TEST(FallbackBudget, StopsOnlyWhenMostOfTheWindowFailed) {
  FallbackBudget b(1.0, 1e-3, 0.5);
  EXPECT_EQ(b.windowSteps(), 1000u);
  // one failure in ten, for a minute: never
  for (int k = 0; k < 60000; ++k) ASSERT_FALSE(b.observe(k % 10 == 0)) << k;
  EXPECT_EQ(b.count(), 100);
  // a continuous failure: stops after the 500 + the 100 already in the window... within one window
  int k = 0;
  while (!b.observe(true)) ++k;
  EXPECT_GT(k, 300);
  EXPECT_LT(k, 1000);
  EXPECT_GT(b.count(), 500);
}

TEST(FallbackBudget, ShareOneNeverStops) {
  FallbackBudget b(0.5, 1e-3, 1.0);
  for (int k = 0; k < 5000; ++k) ASSERT_FALSE(b.observe(true));
}

TEST(FallbackBudget, OldFailuresLeaveTheWindow) {
  FallbackBudget b(0.1, 1e-3, 0.5);  // 100 steps
  for (int k = 0; k < 50; ++k) EXPECT_FALSE(b.observe(true));
  for (int k = 0; k < 100; ++k) EXPECT_FALSE(b.observe(false));
  EXPECT_EQ(b.count(), 0);
}
