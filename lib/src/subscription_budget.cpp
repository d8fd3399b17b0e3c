#include "lcmtf/subscription_budget.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace lcmtf {

namespace {

// LCM keeps what its C side returned, null when it could not subscribe, in a protected member.
struct SubscriptionAccess : lcm::Subscription {
  static bool made(const lcm::Subscription& subscription) {
    return subscription.*(&SubscriptionAccess::c_subs) != nullptr;
  }
};

}  // namespace

bool subscriptionMade(const lcm::Subscription* subscription) {
  return subscription && SubscriptionAccess::made(*subscription);
}

SubscriptionBudget::SubscriptionBudget(lcm::Subscription* subscription, std::string channel,
                                       std::size_t budget_bytes, int most_messages)
    : subscription_(subscription),
      channel_(std::move(channel)),
      budget_bytes_(budget_bytes),
      most_messages_(most_messages),
      capacity_(most_messages) {
  if (!subscriptionMade(subscription_)) {
    throw std::runtime_error("LCM cannot subscribe to " + channel_ + ": it cannot receive (" +
                             kCannotReceiveWhy + ")");
  }
  subscription_->setQueueCapacity(most_messages);
}

bool SubscriptionBudget::fitAt(std::size_t size, Clock::time_point now) {
  if (most_messages_ <= 0) return false;
  if (now - window_start_ >= kWindow) {
    previous_largest_ = now - window_start_ >= 2 * kWindow ? 0 : largest_;
    largest_ = 0;
    window_start_ = now;
  }
  largest_ = std::max(largest_, size);
  const std::size_t largest = std::max(largest_, previous_largest_);
  int capacity = most_messages_;
  if (largest > 0) {
    const std::size_t fitting = budget_bytes_ / largest;
    capacity = static_cast<int>(std::clamp<std::size_t>(fitting > 0 ? fitting - 1 : 0, 1,
                                                        static_cast<std::size_t>(most_messages_)));
  }
  if (capacity == capacity_) return false;
  subscription_->setQueueCapacity(capacity);
  const bool shortened = capacity < capacity_;
  capacity_ = capacity;
  return shortened;
}

SubscriptionBudget* fitChannel(std::vector<SubscriptionBudget>& budgets, const std::string& channel,
                               std::size_t size) {
  SubscriptionBudget* shortened = nullptr;
  for (SubscriptionBudget& budget : budgets) {
    if (budget.channel() == channel && budget.fit(size)) shortened = &budget;
  }
  return shortened;
}

}  // namespace lcmtf
