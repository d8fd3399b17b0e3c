#include "lcmtf/sequence_tracker.hpp"

namespace lcmtf {

SequenceCounts& SequenceCounts::operator+=(const SequenceCounts& other) {
  lost += other.lost;
  reordered += other.reordered;
  duplicated += other.duplicated;
  restarts += other.restarts;
  return *this;
}

void SequenceTracker::startAt(std::int64_t sequence) {
  first_ = sequence;
  highest_ = sequence;
  seen_.reset();
  seen_.set(slot(sequence));
}

void SequenceTracker::restart() {
  first_ = 0;
  highest_ = 0;
  seen_.reset();
}

void SequenceTracker::observe(std::int64_t sequence) {
  if (sequence <= 0) return;
  if (first_ == 0) {
    startAt(sequence);
    return;
  }
  if (sequence > highest_) {
    for (std::int64_t n = highest_ + 1; n < sequence && n - highest_ <= kWindow; ++n) {
      seen_.reset(slot(n));
    }
    seen_.set(slot(sequence));
    counts_.lost += static_cast<std::uint64_t>(sequence - highest_ - 1);  // both positive
    highest_ = sequence;
    return;
  }
  const bool in_window = highest_ - sequence < kWindow;
  const bool seen = in_window && seen_.test(slot(sequence));
  if (!in_window || (sequence == 1 && (seen || first_ > 1))) {
    startAt(sequence);
    ++counts_.restarts;
  } else if (seen) {
    ++counts_.duplicated;
  } else {
    seen_.set(slot(sequence));
    ++counts_.reordered;
    if (sequence > first_) {
      --counts_.lost;  // counted when it was skipped
    } else {
      first_ = sequence;
    }
  }
}

}  // namespace lcmtf
