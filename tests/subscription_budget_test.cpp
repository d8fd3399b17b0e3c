#include "lcmtf/subscription_budget.hpp"

#include <gtest/gtest.h>

namespace lcmtf {
namespace {

struct Ignore {
  void onMessage(const lcm::ReceiveBuffer* /*buffer*/, const std::string& /*channel*/) {}
};

class SubscriptionBudgetTest : public testing::Test {
 protected:
  lcm::Subscription* subscribe() { return lcm_.subscribe("CHANNEL", &Ignore::onMessage, &ignore_); }

  lcm::LCM lcm_{"memq://"};
  Ignore ignore_;
};

TEST_F(SubscriptionBudgetTest, SaysWhenAMessageShortenedTheQueueAndOnlyThen) {
  SubscriptionBudget budget(subscribe(), 100'000, 1000);
  EXPECT_EQ(budget.capacity(), 1000);
  EXPECT_FALSE(budget.fit(50));
  EXPECT_EQ(budget.capacity(), 1000);
  EXPECT_TRUE(budget.fit(30'000));
  EXPECT_EQ(budget.capacity(), 2);
  EXPECT_FALSE(budget.fit(30'000));
  EXPECT_TRUE(budget.fit(60'000));
  EXPECT_EQ(budget.capacity(), 1);
  EXPECT_FALSE(budget.fit(50));  // the largest heard lately still counts
  EXPECT_EQ(budget.capacity(), 1);
}

TEST_F(SubscriptionBudgetTest, ACountOfZeroMeaningNoLimitIsLeftAsItIs) {
  SubscriptionBudget budget(subscribe(), 100'000, 0);
  EXPECT_FALSE(budget.fit(60'000));
  EXPECT_EQ(budget.capacity(), 0);
}

}  // namespace
}  // namespace lcmtf
