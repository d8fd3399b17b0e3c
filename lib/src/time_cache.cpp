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
}

void TimeCache::clearHistory() {
  if (is_static_) return;
  head_ = 0;
  count_ = 0;
  parent_changed_at_ = std::numeric_limits<std::int64_t>::min();
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
      return InsertOutcome::kReplaced;
    }
    if (count_ == ring_.size()) grow();
    // Shift the samples newer than `sample` one place towards the back.
    const std::size_t insert_at = index < count_ ? index + 1 : 0;
    for (std::size_t i = count_; i > insert_at; --i) slot(i) = at(i - 1);
    slot(insert_at) = sample;
    ++count_;
    noteParentChanges(insert_at);
    return InsertOutcome::kAdded;
  }
  if (count_ == ring_.size()) grow();
  slot(count_) = sample;
  ++count_;
  noteParentChanges(count_ - 1);
  const std::int64_t horizon = sample.stamp - cache_time;
  while (at(0).stamp < horizon) {
    head_ = (head_ + 1) & mask_;
    --count_;
  }
  return InsertOutcome::kAdded;
}

// The index of the newest sample at or before `stamp`, or count_ when every sample is newer.
// The first guess assumes evenly spaced samples, which holds for most publishers, so the
// search usually ends within a step or two of it.
std::size_t TimeCache::indexAtOrBefore(std::int64_t stamp) const {
  if (stamp < at(0).stamp) return count_;
  const std::size_t last = count_ - 1;
  const std::int64_t first_stamp = at(0).stamp;
  const std::int64_t span = at(last).stamp - first_stamp;
  if (stamp >= at(last).stamp || span <= 0) return last;

  auto guess = static_cast<std::size_t>(static_cast<double>(stamp - first_stamp) /
                                        static_cast<double>(span) * static_cast<double>(last));
  guess = std::min(guess, last);
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
  if (stamp < at(0).stamp) {
    status = SampleStatus::kPast;
    return at(0).parent;
  }
  if (stamp > at(count_ - 1).stamp) {
    status = SampleStatus::kFuture;
    return at(count_ - 1).parent;
  }
  status = SampleStatus::kOk;
  if (hasSingleParent()) return at(0).parent;
  return at(indexAtOrBefore(stamp)).parent;
}

SampleStatus TimeCache::find(std::int64_t stamp, SampleSpan& span) const {
  if (is_static_) {
    span = SampleSpan{&ring_[0], nullptr, 0.0};
    return SampleStatus::kOk;
  }
  if (count_ == 0) return SampleStatus::kEmpty;
  if (stamp < at(0).stamp) return SampleStatus::kPast;
  if (stamp > at(count_ - 1).stamp) return SampleStatus::kFuture;
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
