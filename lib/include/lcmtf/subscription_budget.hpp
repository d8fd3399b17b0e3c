#pragma once

#include <cstddef>
#include <memory>

#include <lcm/lcm-cpp.hpp>

namespace lcmtf {

/// The count LCM gives a subscription unless told otherwise.
inline constexpr int kLcmDefaultQueueCapacity = 30;
/// The budget of bytes lcmtf's own subscriptions keep what LCM holds for them within.
inline constexpr std::size_t kDefaultQueueBytes = std::size_t{64} << 20;

namespace detail {
class QueueByteBudget;
}

/// Keeps what LCM holds for one subscription, waiting to be handled, within a budget of bytes.
/// LCM 1.3.1 bounds those messages by their count alone (and its udpm provider holds one more
/// than the count), so a peer sending large messages faster than they are handled would make it
/// hold that count times their size. The count given to LCM is one less than fits in the budget
/// of the largest message heard on the subscription in the last 10-20 s, at least one and at
/// most `most_messages` (a count of 0 or less, which LCM gives its own meaning, is left as it
/// is). fit() is called from the subscription's handler, on the thread that handles the LCM.
class SubscriptionBudget {
 public:
  /// Sets `most_messages` on `subscription` now.
  SubscriptionBudget(lcm::Subscription* subscription, std::size_t budget_bytes, int most_messages);
  ~SubscriptionBudget();
  SubscriptionBudget(SubscriptionBudget&&) noexcept;
  SubscriptionBudget& operator=(SubscriptionBudget&&) noexcept;

  /// Fits the count to a message of `size` bytes just come; true when that shortened the queue.
  bool fit(std::size_t size);
  /// The count LCM was given last.
  int capacity() const { return capacity_; }
  lcm::Subscription* subscription() const { return subscription_; }

 private:
  lcm::Subscription* subscription_;
  std::unique_ptr<detail::QueueByteBudget> budget_;
  int capacity_;
  bool budgeted_;
};

}  // namespace lcmtf
