#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

namespace lcmtf {

/// The count LCM gives a subscription unless told otherwise.
inline constexpr int kLcmDefaultQueueCapacity = 30;
/// The budget of bytes lcmtf's own subscriptions keep what LCM holds for them within.
inline constexpr std::size_t kDefaultQueueBytes = std::size_t{64} << 20;

/// Whether LCM made `subscription`: its C++ side returns one even when its C side could not
/// subscribe, as when the LCM cannot receive (a udpm LCM whose self test failed).
bool subscriptionMade(const lcm::Subscription* subscription);
/// Why an LCM cannot make subscriptions, for the messages that say it cannot receive.
inline constexpr const char* kCannotReceiveWhy =
    "with udpm, its self test failed: no route brings multicast back to this machine, or the "
    "port cannot be bound";

/// Keeps what LCM holds for one subscription, waiting to be handled, within a budget of bytes.
/// LCM 1.3.1 bounds those messages by their count alone (and its udpm provider holds one more
/// than the count), so a peer sending large messages faster than they are handled would make it
/// hold that count times their size. The count given to LCM is one less than fits in the budget
/// of the largest message heard on the subscription lately (in the last one to two windows), at
/// least one and at most `most_messages` (a count of 0 or less, which LCM gives its own meaning,
/// is left as it is). fit() is called from the subscription's handler, on the thread that
/// handles the LCM.
class SubscriptionBudget {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr Clock::duration kWindow = std::chrono::seconds(10);

  /// Sets `most_messages` on `subscription` (to `channel`) now. A subscription LCM could not
  /// make (it cannot receive) throws std::runtime_error naming the channel.
  SubscriptionBudget(lcm::Subscription* subscription, std::string channel, std::size_t budget_bytes,
                     int most_messages);

  /// Fits the count to a message of `size` bytes just come; true when that shortened the queue.
  bool fit(std::size_t size) { return fitAt(size, Clock::now()); }
  /// fit() for a message that came at `now`.
  bool fitAt(std::size_t size, Clock::time_point now);
  /// The count LCM was given last.
  int capacity() const { return capacity_; }
  const std::string& channel() const { return channel_; }
  lcm::Subscription* subscription() const { return subscription_; }

 private:
  lcm::Subscription* subscription_;
  std::string channel_;
  std::size_t budget_bytes_;
  int most_messages_;
  int capacity_;
  Clock::time_point window_start_{};
  std::size_t largest_ = 0;           // in the window from window_start_
  std::size_t previous_largest_ = 0;  // in the window before it
};

/// fit() on the budget in `budgets` for `channel` (a handler serving several channels): the
/// budget whose queue that shortened, or null.
SubscriptionBudget* fitChannel(std::vector<SubscriptionBudget>& budgets, const std::string& channel,
                               std::size_t size);

}  // namespace lcmtf
