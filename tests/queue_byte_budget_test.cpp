#include "queue_byte_budget.hpp"

#include <gtest/gtest.h>

namespace lcmtf::detail {
namespace {

using std::chrono::seconds;
using Clock = QueueByteBudget::Clock;

const Clock::time_point kStart = Clock::time_point{} + std::chrono::hours(1);

TEST(QueueByteBudget, MessagesThatFitManyTimesOverKeepTheWholeCount) {
  QueueByteBudget budget(64 << 20, 1000);
  EXPECT_EQ(budget.capacityAfter(60'000, kStart), 1000);
  EXPECT_EQ(budget.capacityAfter(0, kStart), 1000);
}

// With the one message LCM holds beyond the count, what it holds fits in the budget.
TEST(QueueByteBudget, LargerMessagesGetOneLessThanFitsInTheBudgetAndAtLeastOne) {
  QueueByteBudget budget(1'000'000, 1000);
  EXPECT_EQ(budget.capacityAfter(300'000, kStart), 2);
  EXPECT_EQ(budget.capacityAfter(250'000, kStart), 2);  // the largest heard sets it
  EXPECT_EQ(budget.capacityAfter(400'000, kStart), 1);
  EXPECT_EQ(budget.capacityAfter(5'000'000, kStart), 1);
}

TEST(QueueByteBudget, ALargeMessageCountsForOneToTwoWindows) {
  QueueByteBudget budget(1'000'000, 1000);
  EXPECT_EQ(budget.capacityAfter(250'000, kStart), 3);
  EXPECT_EQ(budget.capacityAfter(100, kStart + seconds(9)), 3);
  EXPECT_EQ(budget.capacityAfter(100, kStart + seconds(10)), 3);  // the window before
  EXPECT_EQ(budget.capacityAfter(100, kStart + seconds(19)), 3);
  EXPECT_EQ(budget.capacityAfter(100, kStart + seconds(20)), 1000);
}

TEST(QueueByteBudget, AfterALongSilenceNothingHeardBeforeCounts) {
  QueueByteBudget budget(1'000'000, 1000);
  EXPECT_EQ(budget.capacityAfter(250'000, kStart), 3);
  EXPECT_EQ(budget.capacityAfter(100, kStart + seconds(25)), 1000);
}

}  // namespace
}  // namespace lcmtf::detail
