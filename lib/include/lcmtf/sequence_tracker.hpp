#pragma once

#include <bitset>
#include <cstdint>

namespace lcmtf {

/// What went wrong on the way in one sender's numbered stream (tf_message_t::sequence).
struct SequenceCounts {
  std::uint64_t lost = 0;        ///< numbers skipped that have not arrived since
  std::uint64_t reordered = 0;   ///< arrived after a higher number
  std::uint64_t duplicated = 0;  ///< arrived again
  std::uint64_t restarts = 0;    ///< the numbers began again (a restarted sender, a log replayed)

  SequenceCounts& operator+=(const SequenceCounts& other);
};

/// Follows the numbers 1, 2, 3, ... of one sender on one channel and counts batches lost,
/// reordered and duplicated. A number far below the highest, or 1 again, is a restart, not a loss.
class SequenceTracker {
 public:
  /// How far below the highest number a batch still counts as late rather than as a restart.
  static constexpr std::int64_t kWindow = 256;

  /// Notes one batch's number (0 or less: not numbered, ignored).
  void observe(std::int64_t sequence);
  /// Forgets the numbers seen: the next one starts the stream afresh.
  void restart();
  const SequenceCounts& counts() const { return counts_; }

 private:
  std::size_t slot(std::int64_t sequence) const {
    return static_cast<std::size_t>(sequence % kWindow);
  }
  void startAt(std::int64_t sequence);

  std::int64_t first_ = 0;  // 0: nothing heard yet
  std::int64_t highest_ = 0;
  std::bitset<kWindow> seen_;  // of the numbers in (highest_ - kWindow, highest_]
  SequenceCounts counts_;
};

}  // namespace lcmtf
