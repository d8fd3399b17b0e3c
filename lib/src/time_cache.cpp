#include "time_cache.hpp"

#include <algorithm>

namespace lcmtf::detail {

void TimeCache::setStatic(FrameId parent, const Transform& transform) {
  stamps_.clear();
  parents_.clear();
  transforms_.clear();
  anchored_.clear();
  anchoring_ = false;
  static_value_ = EdgeValue{parent, transform};
  mask_ = 0;
  head_ = 0;
  count_ = 1;
  is_static_ = true;
  parent_changed_at_ = std::numeric_limits<std::int64_t>::min();
  refreshEnds();
}

void TimeCache::clearHistory() {
  if (is_static_) return;
  head_ = 0;
  count_ = 0;
  parent_changed_at_ = std::numeric_limits<std::int64_t>::min();
  refreshEnds();
}

void TimeCache::refreshEnds() {
  single_parent_from_ = std::numeric_limits<std::int64_t>::max();
  if (count_ == 0) {
    oldest_stamp_ = newest_stamp_ = 0;
    oldest_parent_ = newest_parent_ = kNoFrame;
    return;
  }
  if (is_static_) {
    oldest_stamp_ = newest_stamp_ = 0;
    oldest_parent_ = newest_parent_ = static_value_.parent;
    samples_per_utime_ = 0.0;
    return;
  }
  oldest_stamp_ = stampAt(0);
  oldest_parent_ = parentOf(0);
  newest_stamp_ = stampAt(count_ - 1);
  newest_parent_ = parentOf(count_ - 1);
  newest_rotation_ = transformAt(count_ - 1).rotation;
  samples_per_utime_ =
      newest_stamp_ > oldest_stamp_
          ? static_cast<double>(count_ - 1) / static_cast<double>(newest_stamp_ - oldest_stamp_)
          : 0.0;
  if (hasSingleParent()) single_parent_from_ = oldest_stamp_;
}

void TimeCache::put(std::size_t index, std::int64_t stamp, FrameId parent,
                    const Transform& transform, const Transform* anchor_T_parent) {
  const std::size_t at = slot(index);
  stamps_[at].stamp = stamp;
  parents_[at] = parent;
  transforms_.store(at, transform);
  if (anchoring_) anchored_.store(at, anchoredValue(anchor_T_parent, transform));
}

void TimeCache::move(std::size_t from, std::size_t to) {
  const std::size_t source = slot(from);
  const std::size_t destination = slot(to);
  stamps_[destination] = stamps_[source];
  parents_[destination] = parents_[source];
  transforms_.store(destination, transforms_[source]);
  if (anchoring_) anchored_.store(destination, anchored_[source]);
}

void TimeCache::refreshArc(std::size_t index) {
  if (index + 1 >= count_) return;
  stamps_[slot(index)].arc_to_next =
      signedArcSquared(transformAt(index).rotation, transformAt(index + 1).rotation);
}

// Until now every anchor was the identity: each anchored value is the sample itself.
void TimeCache::startAnchoring() {
  anchoring_ = true;
  TransformRing(transforms_.size()).swap(anchored_);
  for (std::size_t i = 0; i < count_; ++i) anchored_.store(slot(i), transformAt(i));
}

void TimeCache::noteParentChanges(std::size_t index) {
  if (index > 0 && parentOf(index - 1) != parentOf(index)) {
    parent_changed_at_ = std::max(parent_changed_at_, stampAt(index));
  }
  if (index + 1 < count_ && parentOf(index + 1) != parentOf(index)) {
    parent_changed_at_ = std::max(parent_changed_at_, stampAt(index + 1));
  }
}

// Grows straight to the size the edge's rate so far says a full window needs, so that an edge
// reaches its working size after one small copy rather than a series of doublings (whose last
// copies, of every busy edge at once, stall a listener).
void TimeCache::grow(std::int64_t cache_time, std::size_t most_samples) {
  constexpr std::size_t kLargestJump = std::size_t{1} << 16;
  std::size_t wanted = std::max<std::size_t>(16, stamps_.size() * 2);
  std::size_t largest = 16;
  while (largest < most_samples && largest < (std::size_t{1} << 40)) largest *= 2;
  if (count_ >= 2 && newest_stamp_ > oldest_stamp_ && cache_time > 0) {
    const double window_samples = static_cast<double>(count_ - 1) *
                                      static_cast<double>(cache_time) /
                                      static_cast<double>(newest_stamp_ - oldest_stamp_) +
                                  1.0;
    const double with_margin = std::min(window_samples + 16.0, double(kLargestJump));
    while (static_cast<double>(wanted) < with_margin) wanted *= 2;
  }
  wanted = std::min(wanted, largest);
  UnfilledArray<SampleTime> stamps(wanted);
  UnfilledArray<FrameId> parents(wanted);
  TransformRing transforms(wanted);
  TransformRing anchored(anchoring_ ? wanted : 0);
  for (std::size_t i = 0; i < count_; ++i) {
    stamps[i] = stamps_[slot(i)];
    parents[i] = parentOf(i);
    transforms.store(i, transformAt(i));
    if (anchoring_) anchored.store(i, anchored_[slot(i)]);
  }
  stamps_.swap(stamps);
  parents_.swap(parents);
  transforms_.swap(transforms);
  anchored_.swap(anchored);
  mask_ = wanted - 1;
  head_ = 0;
}

InsertOutcome TimeCache::insert(const EdgeSample& sample, std::int64_t cache_time,
                                const Transform* anchor_T_parent, std::size_t most_samples) {
  most_samples = std::max<std::size_t>(most_samples, 2);
  if (is_static_) {
    mask_ = 0;
    count_ = 0;
    is_static_ = false;
  }
  if (isTooOld(sample.stamp, cache_time)) return InsertOutcome::kTooOld;
  if (isFullAndOlder(sample.stamp, most_samples)) return InsertOutcome::kFullAndOlder;
  if (anchor_T_parent && !anchoring_) startAnchoring();
  if (count_ > 0 && sample.stamp <= newest_stamp_) {
    std::size_t index = indexAtOrBefore(sample.stamp);
    if (index < count_ && stampAt(index) == sample.stamp) {
      put(index, sample.stamp, sample.parent, sample.transform, anchor_T_parent);
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
    if (count_ == stamps_.size()) grow(cache_time, most_samples);
    // Shift the samples newer than `sample` one place towards the back.
    const std::size_t insert_at = dropped || index < count_ ? index + 1 : 0;
    for (std::size_t i = count_; i > insert_at; --i) move(i - 1, i);
    put(insert_at, sample.stamp, sample.parent, sample.transform, anchor_T_parent);
    ++count_;
    refreshArcsAround(insert_at);
    noteParentChanges(insert_at);
    refreshEnds();
    return dropped ? InsertOutcome::kAddedDroppingOldest : InsertOutcome::kAdded;
  }
  const bool dropped = count_ >= most_samples;
  if (dropped) dropOldest();
  if (count_ == stamps_.size()) grow(cache_time, most_samples);
  // From the newest sample's copy: its slot in the ring may have left the cache by now.
  if (count_ > 0) {
    stamps_[slot(count_ - 1)].arc_to_next =
        signedArcSquared(newest_rotation_, sample.transform.rotation);
  }
  put(count_, sample.stamp, sample.parent, sample.transform, anchor_T_parent);
  ++count_;
  noteParentChanges(count_ - 1);
  const std::int64_t horizon = saturatingSubtract(sample.stamp, cache_time);
  while (stampAt(0) < horizon) dropOldest();
  refreshEnds();
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
    return static_value_.parent;
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
