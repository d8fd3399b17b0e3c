#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>

namespace lcmtf::detail {

/// LCM 1.3.1 bounds the messages it holds for a subscription, waiting to be handled, by their
/// count alone: a peer sending large messages faster than they are handled makes it hold that
/// count times their size (and its udpm provider holds one message more than the count). This
/// turns a budget in bytes into the count to give it: one less than the budget over the largest
/// message heard on the channel lately (in the last one to two windows), at least one and at
/// most `most_messages`.
class QueueByteBudget {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr Clock::duration kWindow = std::chrono::seconds(10);

  QueueByteBudget(std::size_t budget_bytes, int most_messages)
      : budget_bytes_(budget_bytes), most_messages_(std::max(most_messages, 1)) {}

  /// The count to allow once a message of `size` bytes has come at `now`.
  int capacityAfter(std::size_t size, Clock::time_point now) {
    if (now - window_start_ >= kWindow) {
      previous_largest_ = now - window_start_ >= 2 * kWindow ? 0 : largest_;
      largest_ = 0;
      window_start_ = now;
    }
    largest_ = std::max(largest_, size);
    const std::size_t largest = std::max(largest_, previous_largest_);
    if (largest == 0) return most_messages_;
    const std::size_t fitting = budget_bytes_ / largest;
    return static_cast<int>(std::clamp<std::size_t>(fitting > 0 ? fitting - 1 : 0, 1,
                                                    static_cast<std::size_t>(most_messages_)));
  }

 private:
  std::size_t budget_bytes_;
  int most_messages_;
  Clock::time_point window_start_{};
  std::size_t largest_ = 0;
  std::size_t previous_largest_ = 0;
};

}  // namespace lcmtf::detail
