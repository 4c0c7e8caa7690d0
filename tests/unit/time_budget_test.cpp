// How a time-budgeted render sizes its passes and when it stops (host/render/time_budget.h).
#include <gtest/gtest.h>

#include "render/time_budget.h"

using namespace vkmc;

TEST(TimeBudget, PassesFillAQuarterOfTheBudgetButNoMoreThanIsLeft) {
  // 0.1 s a sample, budget 4 s: a quarter holds 10 samples.
  EXPECT_EQ(timeBudgetPassSamples(4.0, 0.5, 0.1, 64), 10u);
  // 0.3 s left: 3 samples, and 0.18 s: 2 (rounded), so the last pass ends near the budget, not a quarter past it.
  EXPECT_EQ(timeBudgetPassSamples(4.0, 3.7, 0.1, 64), 3u);
  EXPECT_EQ(timeBudgetPassSamples(4.0, 3.82, 0.1, 64), 2u);
  // At least one sample, at most a full pass.
  EXPECT_EQ(timeBudgetPassSamples(4.0, 3.99, 0.1, 64), 1u);
  EXPECT_EQ(timeBudgetPassSamples(4.0, 5.0, 0.1, 64), 1u);
  EXPECT_EQ(timeBudgetPassSamples(4.0, 0.0, 1e-7, 28), 28u);
  // Absurd inputs stay in range (no overflowing cast).
  EXPECT_EQ(timeBudgetPassSamples(1e12, 0.0, 1e-12, 64), 64u);
  EXPECT_EQ(timeBudgetPassSamples(4.0, 0.0, 0.0, 8), 8u);
}

TEST(TimeBudget, StopsWhereOneMoreSampleWouldEndFurtherPastThanShort) {
  EXPECT_FALSE(timeBudgetSpent(0.0, 100.0, 1.0));   // no budget
  EXPECT_FALSE(timeBudgetSpent(4.0, 3.9, 0.1));     // one more ends at 4.0: on the budget, short of half
  EXPECT_TRUE(timeBudgetSpent(4.0, 3.96, 0.1));     // one more would end 0.06 past, 0.04 short now
  EXPECT_TRUE(timeBudgetSpent(4.0, 4.2, 0.0));      // past it
  EXPECT_FALSE(timeBudgetSpent(4.0, 3.99, 0.0));    // no rate known yet: the budget itself
}
