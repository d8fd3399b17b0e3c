#pragma once

#include <chrono>

namespace lcmtf::detail {

/// Spaces out work whose cost grows with the size of the tree (rebuilding every frame's root
/// path after an edge changed the tree's shape), so that inserts from a peer that changes an edge
/// on every message cannot keep the buffer's thread and exclusive lock busy with it. Work that
/// took less than kFree may run again at once; longer work only once kSpacing times its length
/// has passed since it ended, which keeps it to a tenth of the time at most.
class RefreshBudget {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr Clock::duration kFree = std::chrono::microseconds(50);
  static constexpr int kSpacing = 9;

  bool allows(Clock::time_point now) const { return now >= next_allowed_; }

  void spent(Clock::time_point start, Clock::time_point end) {
    const Clock::duration cost = end - start;
    next_allowed_ = cost < kFree ? Clock::time_point{} : end + kSpacing * cost;
  }

 private:
  Clock::time_point next_allowed_{};
};

}  // namespace lcmtf::detail
