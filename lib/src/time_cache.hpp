#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>

#include "lcmtf/transform.hpp"
#include "prefetch.hpp"
#include "sample_ring.hpp"
#include "slerp_weights.hpp"
#include "unfilled_array.hpp"

namespace lcmtf::detail {

using FrameId = std::uint32_t;
constexpr FrameId kNoFrame = 0;

/// One sample to store: the edge's value at `stamp` (utime).
struct EdgeSample {
  std::int64_t stamp = 0;
  FrameId parent = kNoFrame;
  Transform transform;
};

/// Where a time falls in an edge's history.
enum class SampleStatus { kOk, kEmpty, kPast, kFuture };

/// The edge's value at a time, as the samples it comes from: `older` alone when exact (or when
/// the parent changes between the two), else `older` and `newer` mixed by `ratio`.
struct SampleSpan {
  const Transform* older = nullptr;
  const Transform* newer = nullptr;
  double ratio = 0.0;
  FrameId parent = kNoFrame;
  double arc_squared = 0.0;  // signedArcSquared(older, newer) when `newer`
};

enum class InsertOutcome {
  kAdded,
  kAddedDroppingOldest,  // the edge held its most samples: the oldest made room
  kReplaced,
  kTooOld,
  kFullAndOlder,  // the edge held its most samples, all newer than this one
};

/// a - b without overflow: clamped to the int64 range (stamps from the network may be anything).
inline std::int64_t saturatingSubtract(std::int64_t a, std::int64_t b) {
  using Limits = std::numeric_limits<std::int64_t>;
  std::int64_t difference;
  if (__builtin_sub_overflow(a, b, &difference)) return b > 0 ? Limits::min() : Limits::max();
  return difference;
}

/// The history of one edge (child frame -> parent) kept in time order in a ring, or a single
/// static value valid at every time. Each sample fills one cache line, its arc to the next
/// beside its transform, with the stamps kept side by side apart from them (SampleRing);
/// parents are kept a sample apiece only once the edge has had two.
class TimeCache {
 public:
  bool isStatic() const { return is_static_; }
  bool empty() const { return count_ == 0; }
  std::size_t size() const { return count_; }
  /// How many samples the edge has room for before it grows.
  std::size_t capacity() const { return samples_.size(); }

  /// Makes the edge static with this value, dropping any history.
  void setStatic(FrameId parent, const Transform& transform);
  /// Adds a sample in time order (the edge becomes dynamic), pruning samples older than
  /// `cache_time` behind the newest; a sample already older than that window is refused. An
  /// edge holds at most `most_samples` (at least 2): beyond that its oldest sample makes room,
  /// and a sample older than all it holds is refused.
  InsertOutcome insert(const EdgeSample& sample, std::int64_t cache_time,
                       std::size_t most_samples = kUnbounded);
  static constexpr std::size_t kUnbounded = static_cast<std::size_t>(-1);
  /// Whether every sample kept is the same whole number of microseconds (below 2^32) after the
  /// one before, as a steady publisher's are.
  bool isSteady() const { return steady_from_ <= oldest_stamp_ && steady_interval_ != 0; }
  /// Whether every sample kept has the same parent.
  bool hasSingleParent() const { return parent_changed_at_ <= oldest_stamp_; }
  /// Whether the edge is dynamic and its samples have more than one parent.
  bool changesParent() const { return !is_static_ && count_ > 0 && !hasSingleParent(); }
  /// Whether insert() would refuse a sample at `stamp` as older than the history kept.
  bool isTooOld(std::int64_t stamp, std::int64_t cache_time) const {
    return !is_static_ && count_ > 0 && stamp < saturatingSubtract(newest_stamp_, cache_time);
  }
  /// Whether insert() would refuse a sample at `stamp` as older than every sample of an edge
  /// holding `most_samples` already.
  bool isFullAndOlder(std::int64_t stamp, std::size_t most_samples) const {
    return !is_static_ && count_ > 0 && count_ >= std::max<std::size_t>(most_samples, 2) &&
           stamp < oldest_stamp_;
  }
  /// Drops the history of a dynamic edge; a static edge keeps its value.
  void clearHistory();

  /// A static edge's parent and value: the pose of the child in that parent.
  FrameId staticParent() const { return static_parent_; }
  const Transform& staticTransform() const { return static_transform_; }
  std::int64_t oldestStamp() const { return oldest_stamp_; }
  /// The oldest stamp from which spanWithin() may be asked for this edge's samples: the oldest
  /// sample's when all the samples have one parent, else none (the int64 maximum).
  std::int64_t singleParentFrom() const { return single_parent_from_; }
  /// Whether spanWithin() may be asked for this edge's samples at `stamp`.
  bool spansUnderOneParent(std::int64_t stamp) const {
    return single_parent_from_ <= stamp && stamp <= newest_stamp_;
  }
  std::int64_t newestStamp() const { return newest_stamp_; }
  FrameId newestParent() const { return newest_parent_; }

  /// For a lookup at the latest common time, before that time is known: the edge's two newest
  /// samples and the arc between them; false when it has fewer.
  bool newestPair(const Transform*& older, const Transform*& newer, double& arc) const {
    if (count_ < 2) return false;
    const std::size_t at = slot(count_ - 2);
    older = &samples_.transform(at);
    newer = &samples_.transform(slot(count_ - 1));
    arc = samples_.arc(at);
    return true;
  }
  /// The ratio at `stamp` from the older of the two newest samples to the newer, as find()
  /// gives it (1 at the newer's stamp); false when `stamp` is not between them.
  bool ratioInNewestPair(std::int64_t stamp, double& ratio) const {
    if (stamp == newest_stamp_) {
      ratio = 1.0;
      return true;
    }
    const std::int64_t older_stamp =
        isSteady() ? newest_stamp_ - steady_interval_ : stampAt(count_ - 2);
    const std::int64_t offset = stamp - older_stamp;
    if (offset < 0 || stamp > newest_stamp_) return false;
    ratio = ratioPast(offset, newest_stamp_ - older_stamp);
    return true;
  }

  /// The samples that give the edge's value at `stamp` (any stamp for a static edge).
  SampleStatus find(std::int64_t stamp, SampleSpan& span) const;
  /// find() for a dynamic edge whose samples all have one parent and that has data at
  /// `stamp`, without checking either; from `hint` (prefetch()'s answer) when it holds.
  SampleSpan spanWithin(std::int64_t stamp, std::size_t hint) const;
  /// The stamps of the two samples `stamp` falls between, when it falls strictly between two.
  bool samplesAround(std::int64_t stamp, std::int64_t& older, std::int64_t& newer) const {
    if (is_static_ || count_ < 2 || stamp <= oldest_stamp_ || stamp >= newest_stamp_) return false;
    const std::size_t index = indexAtOrBefore(stamp);
    if (stampAt(index) == stamp) return false;
    older = stampAt(index);
    newer = stampAt(index + 1);
    return true;
  }
  /// The parent at `stamp`, whether or not the edge has data there (then its nearest sample's
  /// parent), with the status find() would give; kNoFrame when the edge is empty.
  FrameId parentAt(std::int64_t stamp, SampleStatus& status) const;
  /// Starts loading the samples spanWithin(stamp) will read, so several edges load at once;
  /// returns where it guessed they are, as a hint for spanWithin(). For a dynamic edge with
  /// data at `stamp`.
  std::size_t prefetch(std::int64_t stamp) const;
  /// prefetch()'s hint without the loads, for a caller about to read the samples itself.
  std::size_t hintAt(std::int64_t stamp) const { return count_ < 2 ? kNoHint : guessIndex(stamp); }
  /// Starts loading what inserting a sample newer than all those kept reads and writes: the
  /// oldest stamps (pruning reads them), the newest sample (the arc to the new one reads its
  /// rotation and is written beside it), and the slot and stamp after it, the slot unless
  /// prefetchNextSlot() loaded it already.
  void prefetchInsert(bool next_slot_loaded) const {
    if (count_ < 2) return;
    prefetchLine(samples_.stampAddress(slot(0)));
    prefetchLineToWrite(samples_.address(slot(count_ - 1)));
    if (count_ < samples_.size()) {
      const std::size_t next = slot(count_);
      if (!next_slot_loaded) prefetchLineToWrite(samples_.address(next));
      prefetchLineToWrite(samples_.stampAddress(next));
    }
  }
  /// Starts loading, to write, the slot that the next sample newer than all those kept goes
  /// to.
  void prefetchNextSlot() const {
    if (count_ < samples_.size()) prefetchLineToWrite(samples_.address(slot(count_)));
  }
  /// A hint for spanWithin() at a time near the newest sample (as latest-common-time lookups
  /// ask): the sample before the newest, which spanWithin() checks, so that planning reads no
  /// sample.
  std::size_t hintNearNewest() const { return count_ >= 2 ? count_ - 2 : kNoHint; }
  static constexpr std::size_t kNoHint = static_cast<std::size_t>(-1);

 private:
  /// Starts loading what interpolating from sample `index` to the next reads: both samples
  /// (the arc between them beside the older), and the older's stamp unless the edge is steady,
  /// whose ratios need none. Loading every step's samples while the path is still being
  /// planned costs 4-6 % more instructions a lookup at a given time, and made those lookups
  /// faster: pr2's random ones of buffer_core_bench by about 5 %, the forest's by 5-17 %
  /// (processes with and without it taking turns, fastest and middle runs). The stamp, which
  /// the ratio waits for, is asked for first: asked for last, the lookups of buffer_core_bench
  /// --jitter-us=300 on pr2 and deep_chain ran 8-16 % slower.
  [[gnu::always_inline]] void prefetchSpan(std::size_t index) const {
    const std::size_t at = slot(index);
    if (!isSteady()) prefetchLine(samples_.stampAddress(at));
    prefetchLine(samples_.address(at));
    prefetchLine(samples_.address(slot(index + 1)));
  }
  std::size_t slot(std::size_t index) const {
    const std::size_t at = head_ + index;
    return at >= samples_.size() ? at - samples_.size() : at;
  }
  std::int64_t stampAt(std::size_t index) const { return samples_.stamp(slot(index)); }
  FrameId parentOf(std::size_t index) const {
    return parents_.size() != 0 ? parents_[slot(index)] : only_parent_;
  }
  const Transform& transformAt(std::size_t index) const { return samples_.transform(slot(index)); }
  void put(std::size_t index, std::int64_t stamp, FrameId parent, const Transform& transform);
  /// Starts keeping a parent per sample: until now every sample had only_parent_.
  void keepParents();
  /// Keeps a parent per sample from now on if a sample under `parent` is to join other samples
  /// (those there but the one it is `replacing`, if it is) under another.
  void makeRoomForParent(FrameId parent, bool replacing);
  void move(std::size_t from, std::size_t to);
  /// Works out the arc from sample `index` to the next one, when there is a next one.
  void refreshArc(std::size_t index);
  /// refreshArc() on each side of a sample just stored at `index`.
  void refreshArcsAround(std::size_t index) {
    if (index > 0) refreshArc(index - 1);
    refreshArc(index);
  }
  /// The span of the sample in slot `at` alone, at its own stamp.
  SampleSpan exactSpan(std::size_t at, FrameId parent) const {
    return SampleSpan{&samples_.transform(at), nullptr, 0.0, parent};
  }
  /// The span at `stamp` from sample `index` (at or before it): that sample alone when
  /// `exact`, else it and the next one.
  SampleSpan spanFrom(std::size_t index, std::int64_t stamp, FrameId parent, bool exact) const {
    const std::size_t at = slot(index);
    if (exact) return exactSpan(at, parent);
    return spanBetween(at, slot(index + 1), stamp, parent);
  }
  /// The span at `stamp`, strictly between the samples in slots `at` and `next`.
  SampleSpan spanBetween(std::size_t at, std::size_t next, std::int64_t stamp,
                         FrameId parent) const {
    const std::int64_t older_stamp = samples_.stamp(at);
    const std::int64_t offset = stamp - older_stamp;
    return SampleSpan{&samples_.transform(at), &samples_.transform(next),
                      ratioPast(offset, samples_.stamp(next) - older_stamp), parent,
                      samples_.arc(at)};
  }
  /// The ratio `offset` microseconds past a sample, `interval` before the next one: the offset
  /// times the interval's reciprocal (within an ulp of the quotient), the same to the bit for
  /// the same two stamps whichever way the lookup found them.
  static double ratioPast(std::int64_t offset, std::int64_t interval) {
    return static_cast<double>(offset) * (1.0 / static_cast<double>(interval));
  }
  std::size_t indexAtOrBefore(std::int64_t stamp) const;
  std::size_t searchNear(std::int64_t stamp, std::size_t guess) const;
  std::size_t guessIndex(std::int64_t stamp) const;
  void grow(std::int64_t cache_time, std::size_t most_samples);
  void dropOldest() {
    head_ = head_ + 1 == samples_.size() ? 0 : head_ + 1;
    --count_;
  }
  void noteParentChanges(std::size_t index);
  void refreshEnds();
  /// Notes the interval from the newest sample before, `previous_newest`, to one added after it.
  void noteNewestInterval(std::int64_t previous_newest);
  /// Forgets the edge's interval, after a sample came anywhere but after the newest.
  void forgetInterval() {
    steady_interval_ = 0;
    steady_from_ = std::numeric_limits<std::int64_t>::max();
  }

  // What lookups and inserts of a dynamic edge read come first, together, so that they touch
  // two cache lines of the edge; the static value, which they do not read, comes last.
  // With each sample, what interpolating from it to the next needs to know of the arc between
  // their rotations (signedArcSquared()), worked out once as samples come rather than in every
  // lookup: 8 bytes a sample take about a sixth off the PR2 tree's deepest lookups.
  SampleRing samples_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  // Copies of what lookups read most, so walking the tree touches no sample.
  std::int64_t oldest_stamp_ = 0;
  std::int64_t newest_stamp_ = 0;
  // (count - 1) / (newest - oldest) samples a microsecond, times 2^63 and rounded down, for
  // guessIndex(); at most 2^63 (a sample every microsecond).
  std::uint64_t samples_per_utime_fixed_ = 0;
  std::int64_t single_parent_from_ = std::numeric_limits<std::int64_t>::max();
  // Each sample from the one at steady_from_ on is steady_interval_ microseconds after the one
  // before (0: no such interval known, or one too long to keep).
  std::int64_t steady_from_ = std::numeric_limits<std::int64_t>::max();
  FrameId oldest_parent_ = kNoFrame;
  FrameId newest_parent_ = kNoFrame;
  FrameId only_parent_ = kNoFrame;
  std::uint32_t steady_interval_ = 0;
  FrameId static_parent_ = kNoFrame;
  bool is_static_ = false;
  // The newest stamp at which the parent differs from the sample before; samples up to the
  // oldest one all share a parent when this is not newer than the oldest.
  std::int64_t parent_changed_at_ = std::numeric_limits<std::int64_t>::min();
  // A parent per sample, once the edge has had more than one; until then every sample's parent
  // is only_parent_.
  UnfilledArray<FrameId> parents_;
  // Its parent, static_parent_, is kept with the other frame ids, where it fills padding that
  // Transform's alignment would leave beside it here.
  Transform static_transform_;
};

// Where `stamp` would be if the samples were evenly spaced, as most publishers space them
// (never the newest sample, so that the next one exists); for oldest <= stamp <= newest.
// The offset from the oldest stamp times the samples per microsecond in fixed point: a lookup at
// a given time waits for this index before its samples can load, and one integer
// multiplication takes half as long as converting to a double, multiplying and converting back
// (2 % off wide's deepest lookups in buffer_core_bench).
inline std::size_t TimeCache::guessIndex(std::int64_t stamp) const {
  const std::size_t last = count_ - 1;
  __extension__ using Wide = unsigned __int128;
  const auto twice_offset = static_cast<std::uint64_t>(stamp - oldest_stamp_) * 2;
  const auto guess =
      static_cast<std::size_t>((Wide{twice_offset} * samples_per_utime_fixed_) >> 64);
  return std::min(guess, last - 1);
}

inline std::size_t TimeCache::prefetch(std::int64_t stamp) const {
  const std::size_t guess = hintAt(stamp);
  if (guess != kNoHint) prefetchSpan(guess);
  return guess;
}

// The index of the newest sample at or before `stamp`, or count_ when every sample is newer.
// The guess from even spacing is usually right.
inline std::size_t TimeCache::indexAtOrBefore(std::int64_t stamp) const {
  if (stamp < oldest_stamp_) return count_;
  const std::size_t last = count_ - 1;
  if (stamp >= newest_stamp_ || newest_stamp_ <= oldest_stamp_) return last;
  const std::size_t guess = guessIndex(stamp);
  if (stampAt(guess) <= stamp && stamp < stampAt(guess + 1)) return guess;
  return searchNear(stamp, guess);
}

inline SampleSpan TimeCache::spanWithin(std::int64_t stamp, std::size_t hint) const {
  if (hint != kNoHint) {
    // The hinted pair's slots and stamps serve the span too, found once: 1-3 % of the
    // lookups on pr2 and deep_chain in buffer_core_bench.
    const std::size_t at = slot(hint);
    const std::size_t next = at + 1 == samples_.size() ? 0 : at + 1;
    // A steady edge's stamps are known before its samples load: the ratio need not wait for
    // them. In buffer_core_bench, wide's random, deepest and time-travel lookups 5-6 % faster,
    // pr2's random and latest-time ones 2 %; the deepest of pr2 and deep_chain 2 % slower.
    // Stamps one interval past the hinted sample (where a lookup at the latest common time
    // falls on the newest sample of the edge that sets it) are taken here as well, from one
    // unsigned comparison for 0 < steady_offset <= steady_interval_: 1-3 % off the lookups of
    // buffer_core_bench on pr2, deep_chain and wide.
    const std::int64_t steady_offset =
        stamp - oldest_stamp_ - static_cast<std::int64_t>(hint) * steady_interval_;
    if (steady_from_ <= oldest_stamp_ &&
        static_cast<std::uint64_t>(steady_offset - 1) < steady_interval_) {
      if (steady_offset == steady_interval_) {
        return exactSpan(next, newest_parent_);
      }
      return SampleSpan{&samples_.transform(at), &samples_.transform(next),
                        ratioPast(steady_offset, steady_interval_), newest_parent_,
                        samples_.arc(at)};
    }
    const std::int64_t older_stamp = samples_.stamp(at);
    const std::int64_t newer_stamp = samples_.stamp(next);
    if (older_stamp <= stamp && stamp <= newer_stamp) {
      if (older_stamp == stamp) {
        return exactSpan(at, newest_parent_);
      }
      // A lookup at the latest common time falls on the newest sample of the edge that sets it:
      // taking it here instead of by a search took 4-5 % off pr2's latest-time lookups and 8 %
      // off wide's, with buffer_core_bench run on those rows alone (in whole runs of the bench
      // they moved less than their spread).
      if (stamp == newer_stamp) {
        return exactSpan(next, newest_parent_);
      }
      return spanBetween(at, next, stamp, newest_parent_);
    }
  }
  const std::size_t index = indexAtOrBefore(stamp);
  return spanFrom(index, stamp, newest_parent_, stampAt(index) == stamp);
}

inline SampleStatus TimeCache::find(std::int64_t stamp, SampleSpan& span) const {
  if (is_static_) {
    span = SampleSpan{&static_transform_, nullptr, 0.0, static_parent_};
    return SampleStatus::kOk;
  }
  if (count_ == 0) return SampleStatus::kEmpty;
  if (stamp < oldest_stamp_) return SampleStatus::kPast;
  if (stamp > newest_stamp_) return SampleStatus::kFuture;
  const std::size_t index = indexAtOrBefore(stamp);
  const FrameId parent = hasSingleParent() ? newest_parent_ : parentOf(index);
  // A parent change between the two samples keeps the older one unchanged, as tf does.
  const bool exact =
      stampAt(index) == stamp || (!hasSingleParent() && parentOf(index + 1) != parent);
  span = spanFrom(index, stamp, parent, exact);
  return SampleStatus::kOk;
}

}  // namespace lcmtf::detail
