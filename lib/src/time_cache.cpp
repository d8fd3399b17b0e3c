#include "time_cache.hpp"

#include <algorithm>

namespace lcmtf::detail {

void TimeCache::setStatic(FrameId parent, const Transform& transform) {
  ring_.assign(1, EdgeSample{0, parent, transform});
  mask_ = 0;
  head_ = 0;
  count_ = 1;
  is_static_ = true;
  parent_changed_at_ = std::numeric_limits<std::int64_t>::min();
  refreshEnds();
}

void TimeCache::refreshEnds() {
  if (count_ == 0) {
    oldest_stamp_ = newest_stamp_ = 0;
    oldest_parent_ = newest_parent_ = kNoFrame;
    return;
  }
  oldest_stamp_ = at(0).stamp;
  oldest_parent_ = at(0).parent;
  newest_stamp_ = at(count_ - 1).stamp;
  newest_parent_ = at(count_ - 1).parent;
}

void TimeCache::clearHistory() {
  if (is_static_) return;
  head_ = 0;
  count_ = 0;
  parent_changed_at_ = std::numeric_limits<std::int64_t>::min();
  refreshEnds();
}

void TimeCache::noteParentChanges(std::size_t index) {
  if (index > 0 && at(index - 1).parent != at(index).parent) {
    parent_changed_at_ = std::max(parent_changed_at_, at(index).stamp);
  }
  if (index + 1 < count_ && at(index + 1).parent != at(index).parent) {
    parent_changed_at_ = std::max(parent_changed_at_, at(index + 1).stamp);
  }
}

void TimeCache::grow() {
  const std::size_t new_capacity = std::max<std::size_t>(16, ring_.size() * 2);
  std::vector<EdgeSample> bigger(new_capacity);
  for (std::size_t i = 0; i < count_; ++i) bigger[i] = at(i);
  ring_.swap(bigger);
  mask_ = new_capacity - 1;
  head_ = 0;
}

InsertOutcome TimeCache::insert(const EdgeSample& sample, std::int64_t cache_time) {
  if (is_static_) {
    ring_.clear();
    mask_ = 0;
    count_ = 0;
    is_static_ = false;
  }
  if (isTooOld(sample.stamp, cache_time)) return InsertOutcome::kTooOld;
  if (count_ > 0 && sample.stamp <= newest().stamp) {
    const std::size_t index = indexAtOrBefore(sample.stamp);
    if (index < count_ && at(index).stamp == sample.stamp) {
      slot(index) = sample;
      noteParentChanges(index);
      refreshEnds();
      return InsertOutcome::kReplaced;
    }
    if (count_ == ring_.size()) grow();
    // Shift the samples newer than `sample` one place towards the back.
    const std::size_t insert_at = index < count_ ? index + 1 : 0;
    for (std::size_t i = count_; i > insert_at; --i) slot(i) = at(i - 1);
    slot(insert_at) = sample;
    ++count_;
    noteParentChanges(insert_at);
    refreshEnds();
    return InsertOutcome::kAdded;
  }
  if (count_ == ring_.size()) grow();
  slot(count_) = sample;
  ++count_;
  noteParentChanges(count_ - 1);
  const std::int64_t horizon = saturatingSubtract(sample.stamp, cache_time);
  while (at(0).stamp < horizon) {
    head_ = (head_ + 1) & mask_;
    --count_;
  }
  refreshEnds();
  return InsertOutcome::kAdded;
}

// Where `stamp` would be if the samples were evenly spaced, as most publishers space them;
// for oldest <= stamp < newest.
std::size_t TimeCache::guessIndex(std::int64_t stamp) const {
  const std::size_t last = count_ - 1;
  const auto guess = static_cast<std::size_t>(static_cast<double>(stamp - oldest_stamp_) /
                                              static_cast<double>(newest_stamp_ - oldest_stamp_) *
                                              static_cast<double>(last));
  return std::min(guess, last - 1);
}

void TimeCache::prefetch(std::int64_t stamp) const {
  if (is_static_ || count_ < 2 || stamp <= oldest_stamp_ || stamp >= newest_stamp_) return;
  const std::size_t guess = guessIndex(stamp);
  __builtin_prefetch(&at(guess));
  __builtin_prefetch(reinterpret_cast<const char*>(&at(guess)) + sizeof(EdgeSample));
  __builtin_prefetch(&at(guess + 1));
  __builtin_prefetch(reinterpret_cast<const char*>(&at(guess + 1)) + sizeof(EdgeSample) - 1);
}

// The index of the newest sample at or before `stamp`, or count_ when every sample is newer.
// The guess from even spacing usually ends the search within a step or two.
std::size_t TimeCache::indexAtOrBefore(std::int64_t stamp) const {
  if (stamp < oldest_stamp_) return count_;
  const std::size_t last = count_ - 1;
  if (stamp >= newest_stamp_ || newest_stamp_ <= oldest_stamp_) return last;

  std::size_t guess = guessIndex(stamp);
  for (int step = 0; step < 3; ++step) {
    if (at(guess).stamp > stamp) {
      --guess;
    } else if (at(guess + 1).stamp <= stamp) {
      ++guess;
    } else {
      return guess;
    }
  }
  std::size_t low = 0;  // at(low) <= stamp < at(high)
  std::size_t high = last;
  while (high - low > 1) {
    const std::size_t middle = low + (high - low) / 2;
    if (at(middle).stamp <= stamp) {
      low = middle;
    } else {
      high = middle;
    }
  }
  return low;
}

FrameId TimeCache::parentAt(std::int64_t stamp, SampleStatus& status) const {
  if (is_static_) {
    status = SampleStatus::kOk;
    return ring_[0].parent;
  }
  if (count_ == 0) {
    status = SampleStatus::kEmpty;
    return kNoFrame;
  }
  if (stamp < oldest_stamp_) {
    status = SampleStatus::kPast;
    return oldest_parent_;
  }
  if (stamp > newest_stamp_) {
    status = SampleStatus::kFuture;
    return newest_parent_;
  }
  status = SampleStatus::kOk;
  if (hasSingleParent()) return newest_parent_;
  return at(indexAtOrBefore(stamp)).parent;
}

SampleStatus TimeCache::find(std::int64_t stamp, SampleSpan& span) const {
  if (is_static_) {
    span = SampleSpan{&ring_[0], nullptr, 0.0};
    return SampleStatus::kOk;
  }
  if (count_ == 0) return SampleStatus::kEmpty;
  if (stamp < oldest_stamp_) return SampleStatus::kPast;
  if (stamp > newest_stamp_) return SampleStatus::kFuture;
  const std::size_t index = indexAtOrBefore(stamp);
  const EdgeSample& older = at(index);
  if (older.stamp == stamp) {
    span = SampleSpan{&older, nullptr, 0.0};
    return SampleStatus::kOk;
  }
  const EdgeSample& newer = at(index + 1);
  if (newer.parent != older.parent) {
    span = SampleSpan{&older, nullptr, 0.0};
    return SampleStatus::kOk;
  }
  span = SampleSpan{
      &older, &newer,
      static_cast<double>(stamp - older.stamp) / static_cast<double>(newer.stamp - older.stamp)};
  return SampleStatus::kOk;
}

}  // namespace lcmtf::detail
