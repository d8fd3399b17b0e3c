#include "refresh_budget.hpp"

#include <gtest/gtest.h>

namespace lcmtf::detail {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;
using Clock = RefreshBudget::Clock;

const Clock::time_point kStart = Clock::time_point{} + std::chrono::hours(1);

TEST(RefreshBudget, AllowsTheFirstWork) { EXPECT_TRUE(RefreshBudget().allows(kStart)); }

TEST(RefreshBudget, WorkShorterThanTheFreeLengthMayRunAgainAtOnce) {
  RefreshBudget budget;
  budget.spent(kStart, kStart + microseconds(49));
  EXPECT_TRUE(budget.allows(kStart + microseconds(49)));
}

TEST(RefreshBudget, LongerWorkWaitsNineTimesItsLengthSoItTakesATenthOfTheTimeAtMost) {
  RefreshBudget budget;
  const Clock::time_point end = kStart + milliseconds(1);
  budget.spent(kStart, end);
  EXPECT_FALSE(budget.allows(end));
  EXPECT_FALSE(budget.allows(end + microseconds(8999)));
  EXPECT_TRUE(budget.allows(end + milliseconds(9)));
}

TEST(RefreshBudget, CheapWorkAfterLongWorkLiftsTheWait) {
  RefreshBudget budget;
  budget.spent(kStart, kStart + milliseconds(1));
  const Clock::time_point later = kStart + milliseconds(10);
  budget.spent(later, later + microseconds(10));
  EXPECT_TRUE(budget.allows(later + microseconds(10)));
}

}  // namespace
}  // namespace lcmtf::detail
