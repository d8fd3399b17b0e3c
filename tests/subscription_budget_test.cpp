#include "lcmtf/subscription_budget.hpp"

#include <gtest/gtest.h>

namespace lcmtf {
namespace {

using std::chrono::seconds;
using Clock = SubscriptionBudget::Clock;

const Clock::time_point kStart = Clock::time_point{} + std::chrono::hours(1);

struct Ignore {
  void onMessage(const lcm::ReceiveBuffer* /*buffer*/, const std::string& /*channel*/) {}
};

class SubscriptionBudgetTest : public testing::Test {
 protected:
  SubscriptionBudget budget(std::size_t budget_bytes, int most_messages,
                            const std::string& channel = "CHANNEL") {
    return SubscriptionBudget(lcm_.subscribe(channel, &Ignore::onMessage, &ignore_), channel,
                              budget_bytes, most_messages);
  }
  // The count after a message of `size` bytes at `now`.
  static int countAfter(SubscriptionBudget& budget, std::size_t size, Clock::time_point now) {
    budget.fitAt(size, now);
    return budget.capacity();
  }

  lcm::LCM lcm_{"memq://"};
  Ignore ignore_;
};

TEST_F(SubscriptionBudgetTest, MessagesThatFitManyTimesOverKeepTheWholeCount) {
  SubscriptionBudget fitted = budget(64 << 20, 1000);
  EXPECT_EQ(countAfter(fitted, 60'000, kStart), 1000);
  EXPECT_EQ(countAfter(fitted, 0, kStart), 1000);
}

// With the one message LCM holds beyond the count, what it holds fits in the budget.
TEST_F(SubscriptionBudgetTest, LargerMessagesGetOneLessThanFitsInTheBudgetAndAtLeastOne) {
  SubscriptionBudget fitted = budget(1'000'000, 1000);
  EXPECT_EQ(countAfter(fitted, 300'000, kStart), 2);
  EXPECT_EQ(countAfter(fitted, 250'000, kStart), 2);  // the largest heard sets it
  EXPECT_EQ(countAfter(fitted, 400'000, kStart), 1);
  EXPECT_EQ(countAfter(fitted, 5'000'000, kStart), 1);
}

TEST_F(SubscriptionBudgetTest, ALargeMessageCountsForOneToTwoWindows) {
  SubscriptionBudget fitted = budget(1'000'000, 1000);
  EXPECT_EQ(countAfter(fitted, 250'000, kStart), 3);
  EXPECT_EQ(countAfter(fitted, 100, kStart + seconds(9)), 3);
  EXPECT_EQ(countAfter(fitted, 100, kStart + seconds(10)), 3);  // the window before
  EXPECT_EQ(countAfter(fitted, 100, kStart + seconds(19)), 3);
  EXPECT_EQ(countAfter(fitted, 100, kStart + seconds(20)), 1000);
}

TEST_F(SubscriptionBudgetTest, AfterALongSilenceNothingHeardBeforeCounts) {
  SubscriptionBudget fitted = budget(1'000'000, 1000);
  EXPECT_EQ(countAfter(fitted, 250'000, kStart), 3);
  EXPECT_EQ(countAfter(fitted, 100, kStart + seconds(25)), 1000);
}

TEST_F(SubscriptionBudgetTest, SaysWhenAMessageShortenedTheQueueAndOnlyThen) {
  SubscriptionBudget fitted = budget(100'000, 1000);
  EXPECT_EQ(fitted.capacity(), 1000);
  EXPECT_FALSE(fitted.fit(50));
  EXPECT_EQ(fitted.capacity(), 1000);
  EXPECT_TRUE(fitted.fit(30'000));
  EXPECT_EQ(fitted.capacity(), 2);
  EXPECT_FALSE(fitted.fit(30'000));
  EXPECT_TRUE(fitted.fit(60'000));
  EXPECT_EQ(fitted.capacity(), 1);
  EXPECT_FALSE(fitted.fit(50));  // the largest heard lately still counts
  EXPECT_EQ(fitted.capacity(), 1);
}

TEST_F(SubscriptionBudgetTest, ACountOfZeroMeaningNoLimitIsLeftAsItIs) {
  SubscriptionBudget fitted = budget(100'000, 0);
  EXPECT_FALSE(fitted.fit(60'000));
  EXPECT_EQ(fitted.capacity(), 0);
}

TEST_F(SubscriptionBudgetTest, AMessageFitsOnlyTheBudgetOfItsOwnChannel) {
  std::vector<SubscriptionBudget> budgets;
  budgets.push_back(budget(100'000, 1000, "A"));
  budgets.push_back(budget(100'000, 1000, "B"));
  EXPECT_EQ(fitChannel(budgets, "B", 30'000), &budgets[1]);
  EXPECT_EQ(budgets[0].capacity(), 1000);
  EXPECT_EQ(budgets[1].capacity(), 2);
  EXPECT_EQ(fitChannel(budgets, "B", 30'000), nullptr);  // not shortened again
  EXPECT_EQ(fitChannel(budgets, "C", 30'000), nullptr);
}

}  // namespace
}  // namespace lcmtf
