// How a time-budgeted render sizes its passes and when it stops (host/render/time_budget.h).
#include <gtest/gtest.h>

#include "render/time_budget.h"

using namespace vkmc;

TEST(TimeBudget, PassesFillAQuarterOfTheBudgetButNoMoreThanReachItsEnd) {
  // 0.125 s a sample, budget 4 s: a quarter holds 8 samples.
  EXPECT_EQ(timeBudgetPassSamples(4.0, 0.5, 0.125, 64), 8u);
  // 0.25 s left: 2 samples; 0.2 s: 2 (1.6, rounded up: the render never stops short of its budget); so the last
  // pass ends within a sample of the budget, not up to a quarter past it.
  EXPECT_EQ(timeBudgetPassSamples(4.0, 3.75, 0.125, 64), 2u);
  EXPECT_EQ(timeBudgetPassSamples(4.0, 3.8, 0.125, 64), 2u);
  // At least one sample, at most a full pass.
  EXPECT_EQ(timeBudgetPassSamples(4.0, 3.99, 0.125, 64), 1u);
  EXPECT_EQ(timeBudgetPassSamples(4.0, 5.0, 0.125, 64), 1u);
  EXPECT_EQ(timeBudgetPassSamples(4.0, 0.0, 1e-7, 28), 28u);
  // Absurd inputs stay in range (no overflowing cast).
  EXPECT_EQ(timeBudgetPassSamples(1e12, 0.0, 1e-12, 64), 64u);
  EXPECT_EQ(timeBudgetPassSamples(4.0, 0.0, 0.0, 8), 8u);
}

TEST(TimeBudget, SpentOnceItsTimeHasPassed) {
  EXPECT_FALSE(timeBudgetSpent(0.0, 100.0));  // no budget
  EXPECT_FALSE(timeBudgetSpent(4.0, 3.99));
  EXPECT_TRUE(timeBudgetSpent(4.0, 4.0));
  EXPECT_TRUE(timeBudgetSpent(4.0, 4.2));
}
