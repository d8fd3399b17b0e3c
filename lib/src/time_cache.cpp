#include "time_cache.hpp"

#include <algorithm>

namespace lcmtf::detail {

void TimeCache::setStatic(FrameId parent, const Transform& transform) {
  samples_.clear();
  parents_.clear();
  static_parent_ = parent;
  static_transform_ = transform;
  head_ = 0;
  count_ = 1;
  is_static_ = true;
  parent_changed_at_ = std::numeric_limits<std::int64_t>::min();
  forgetInterval();
  refreshEnds();
}

void TimeCache::clearHistory() {
  if (is_static_) return;
  head_ = 0;
  count_ = 0;
  parents_.clear();
  parent_changed_at_ = std::numeric_limits<std::int64_t>::min();
  forgetInterval();
  refreshEnds();
}

[[gnu::always_inline]] inline void TimeCache::noteNewestInterval(std::int64_t previous_newest) {
  const std::int64_t interval = saturatingSubtract(newest_stamp_, previous_newest);
  if (interval == steady_interval_) return;
  steady_interval_ = interval <= std::numeric_limits<std::uint32_t>::max()
                         ? static_cast<std::uint32_t>(interval)
                         : 0;
  steady_from_ = previous_newest;
}

// This and the two helpers below are inlined into insert(): their calls took 4 % of an insert
// on the wide tree of buffer_core_bench.
[[gnu::always_inline]] inline void TimeCache::refreshEnds() {
  single_parent_from_ = std::numeric_limits<std::int64_t>::max();
  if (count_ == 0) {
    oldest_stamp_ = newest_stamp_ = 0;
    oldest_parent_ = newest_parent_ = kNoFrame;
    return;
  }
  if (is_static_) {
    oldest_stamp_ = newest_stamp_ = 0;
    oldest_parent_ = newest_parent_ = static_parent_;
    samples_per_utime_fixed_ = 0;
    return;
  }
  oldest_stamp_ = stampAt(0);
  oldest_parent_ = parentOf(0);
  newest_stamp_ = stampAt(count_ - 1);
  newest_parent_ = parentOf(count_ - 1);
  const double samples_per_utime =
      newest_stamp_ > oldest_stamp_
          ? static_cast<double>(count_ - 1) / static_cast<double>(newest_stamp_ - oldest_stamp_)
          : 0.0;
  constexpr std::uint64_t kFixedOne = std::uint64_t{1} << 63;
  samples_per_utime_fixed_ = samples_per_utime < 1.0
                                 ? static_cast<std::uint64_t>(static_cast<std::int64_t>(
                                       samples_per_utime * static_cast<double>(kFixedOne)))
                                 : kFixedOne;
  if (hasSingleParent()) single_parent_from_ = oldest_stamp_;
}

void TimeCache::keepParents() {
  UnfilledArray<FrameId>(samples_.size()).swap(parents_);
  for (std::size_t i = 0; i < count_; ++i) parents_[slot(i)] = only_parent_;
}

void TimeCache::put(std::size_t index, std::int64_t stamp, FrameId parent,
                    const Transform& transform) {
  const std::size_t at = slot(index);
  samples_.store(at, stamp, transform);
  if (parents_.size() == 0) {
    only_parent_ = parent;
  } else {
    parents_[at] = parent;
  }
}

void TimeCache::makeRoomForParent(FrameId parent, bool replacing) {
  const std::size_t staying = replacing ? count_ - 1 : count_;
  if (parents_.size() == 0 && staying > 0 && parent != only_parent_) keepParents();
}

void TimeCache::move(std::size_t from, std::size_t to) {
  const std::size_t source = slot(from);
  const std::size_t destination = slot(to);
  samples_.copy(samples_, source, destination);
  if (parents_.size() != 0) parents_[destination] = parents_[source];
}

[[gnu::always_inline]] inline void TimeCache::refreshArc(std::size_t index) {
  if (index + 1 >= count_) return;
  samples_.setArc(slot(index),
                  signedArcSquared(transformAt(index).rotation, transformAt(index + 1).rotation));
}

[[gnu::always_inline]] inline void TimeCache::noteParentChanges(std::size_t index) {
  if (index > 0 && parentOf(index - 1) != parentOf(index)) {
    parent_changed_at_ = std::max(parent_changed_at_, stampAt(index));
  }
  if (index + 1 < count_ && parentOf(index + 1) != parentOf(index)) {
    parent_changed_at_ = std::max(parent_changed_at_, stampAt(index + 1));
  }
}

// Grows by a quarter, or to the size the edge's rate so far says a full window needs when that
// is at most double: a steady edge ends a few samples above its window (which keeps a sample
// near 64 bytes), and one with a short history stays within a quarter of it. Growing by half
// instead left an edge of 20 samples room for 28, which cost the 100,000-frame forest of
// buffer_core_bench 220 bytes a frame; the extra copies are made once, while the edge is new.
void TimeCache::grow(std::int64_t cache_time, std::size_t most_samples) {
  constexpr std::size_t kSmallest = 4;
  const std::size_t size = samples_.size();
  std::size_t wanted = std::max(kSmallest, size + std::max<std::size_t>(1, size / 4));
  if (count_ >= 2 && newest_stamp_ > oldest_stamp_ && cache_time > 0) {
    const double window = static_cast<double>(count_ - 1) * static_cast<double>(cache_time) /
                              static_cast<double>(newest_stamp_ - oldest_stamp_) +
                          1.0;
    const double with_margin = window + window / 64.0 + 4.0;
    if (with_margin > static_cast<double>(size) && with_margin <= 2.0 * static_cast<double>(size)) {
      wanted = static_cast<std::size_t>(with_margin);
    }
  }
  wanted = std::max(std::min(wanted, std::max(most_samples, kSmallest)), count_ + 1);
  SampleRing samples(wanted);
  UnfilledArray<FrameId> parents(parents_.size() != 0 ? wanted : 0);
  for (std::size_t i = 0; i < count_; ++i) {
    samples.copy(samples_, slot(i), i);
    if (parents.size() != 0) parents[i] = parents_[slot(i)];
  }
  samples_.swap(samples);
  parents_.swap(parents);
  head_ = 0;
}

InsertOutcome TimeCache::insert(const EdgeSample& sample, std::int64_t cache_time,
                                std::size_t most_samples) {
  most_samples = std::max<std::size_t>(most_samples, 2);
  if (is_static_) {
    count_ = 0;
    head_ = 0;
    is_static_ = false;
  }
  if (isTooOld(sample.stamp, cache_time)) return InsertOutcome::kTooOld;
  if (isFullAndOlder(sample.stamp, most_samples)) return InsertOutcome::kFullAndOlder;
  if (count_ > 0 && sample.stamp <= newest_stamp_) {
    std::size_t index = indexAtOrBefore(sample.stamp);
    if (index < count_ && stampAt(index) == sample.stamp) {
      makeRoomForParent(sample.parent, true);
      put(index, sample.stamp, sample.parent, sample.transform);
      refreshArcsAround(index);
      noteParentChanges(index);
      refreshEnds();
      return InsertOutcome::kReplaced;
    }
    // A full edge's oldest sample makes room (isFullAndOlder() refused one older than all).
    const bool dropped = count_ >= most_samples;
    if (dropped) {
      dropOldest();
      --index;
    }
    if (count_ == samples_.size()) grow(cache_time, most_samples);
    makeRoomForParent(sample.parent, false);
    // Shift the samples newer than `sample` one place towards the back.
    const std::size_t insert_at = dropped || index < count_ ? index + 1 : 0;
    for (std::size_t i = count_; i > insert_at; --i) move(i - 1, i);
    put(insert_at, sample.stamp, sample.parent, sample.transform);
    ++count_;
    refreshArcsAround(insert_at);
    noteParentChanges(insert_at);
    forgetInterval();
    refreshEnds();
    return dropped ? InsertOutcome::kAddedDroppingOldest : InsertOutcome::kAdded;
  }
  const bool dropped = count_ >= most_samples;
  const std::int64_t previous_newest = count_ > 0 ? newest_stamp_ : sample.stamp;
  if (dropped) dropOldest();
  if (count_ == samples_.size()) grow(cache_time, most_samples);
  makeRoomForParent(sample.parent, false);
  put(count_, sample.stamp, sample.parent, sample.transform);
  ++count_;
  if (count_ > 1) refreshArc(count_ - 2);
  noteParentChanges(count_ - 1);
  const std::int64_t horizon = saturatingSubtract(sample.stamp, cache_time);
  while (stampAt(0) < horizon) dropOldest();
  refreshEnds();
  noteNewestInterval(previous_newest);
  return dropped ? InsertOutcome::kAddedDroppingOldest : InsertOutcome::kAdded;
}

// The guess was wrong: a few steps from it usually find the place, else a binary search.
std::size_t TimeCache::searchNear(std::int64_t stamp, std::size_t guess) const {
  const std::size_t last = count_ - 1;
  for (int step = 0; step < 3; ++step) {
    if (stampAt(guess) > stamp) {
      --guess;
    } else if (stampAt(guess + 1) <= stamp) {
      ++guess;
    } else {
      return guess;
    }
  }
  std::size_t low = 0;  // stampAt(low) <= stamp < stampAt(high)
  std::size_t high = last;
  while (high - low > 1) {
    const std::size_t middle = low + (high - low) / 2;
    if (stampAt(middle) <= stamp) {
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
    return static_parent_;
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
  return parentOf(indexAtOrBefore(stamp));
}

}  // namespace lcmtf::detail
