#include "lcmtf/subscription_budget.hpp"

#include "queue_byte_budget.hpp"

namespace lcmtf {

SubscriptionBudget::SubscriptionBudget(lcm::Subscription* subscription, std::size_t budget_bytes,
                                       int most_messages)
    : subscription_(subscription),
      budget_(std::make_unique<detail::QueueByteBudget>(budget_bytes, most_messages)),
      capacity_(most_messages),
      budgeted_(most_messages > 0) {
  subscription_->setQueueCapacity(most_messages);
}

SubscriptionBudget::~SubscriptionBudget() = default;
SubscriptionBudget::SubscriptionBudget(SubscriptionBudget&&) noexcept = default;
SubscriptionBudget& SubscriptionBudget::operator=(SubscriptionBudget&&) noexcept = default;

bool SubscriptionBudget::fit(std::size_t size) {
  if (!budgeted_) return false;
  const int capacity = budget_->capacityAfter(size, detail::QueueByteBudget::Clock::now());
  if (capacity == capacity_) return false;
  subscription_->setQueueCapacity(capacity);
  const bool shortened = capacity < capacity_;
  capacity_ = capacity;
  return shortened;
}

}  // namespace lcmtf
