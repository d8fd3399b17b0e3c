#include "lcmtf/buffer_core.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "buffer_core_impl.hpp"
#include "compose.hpp"
#include "lcmtf/printable.hpp"
#include "name_words.hpp"
#include "prefetch.hpp"
#include "transform_check.hpp"

namespace lcmtf {

const char* describe(InsertRejection kind) {
  switch (kind) {
    case InsertRejection::kNonFinite:
      return "non-finite value";
    case InsertRejection::kBadQuaternion:
      return "invalid quaternion";
    case InsertRejection::kEmptyFrameName:
      return "empty frame name";
    case InsertRejection::kSelfParented:
      return "frame is its own parent";
    case InsertRejection::kOlderThanHistory:
      return "older than the history kept";
    case InsertRejection::kEdgeFull:
      return "older than every sample of a full edge";
    case InsertRejection::kCount:
      break;
  }
  return "unknown";
}

namespace {

// Enough for the whole cache time at 1.2 kHz, and never fewer than a slow edge needs.
std::size_t defaultMostSamplesPerEdge(Duration cache_time) {
  constexpr double kCoveredRate = 1200.0;
  const double seconds = std::chrono::duration<double>(cache_time).count();
  return static_cast<std::size_t>(std::clamp(std::ceil(seconds * kCoveredRate), 64.0, 1e12));
}

}  // namespace

BufferCore::Impl::Impl(Duration cache_time)
    : cache_time_(cache_time.count()),
      most_samples_per_edge_(defaultMostSamplesPerEdge(cache_time)),
      reporter_([](const std::string& message) { std::cerr << "lcmtf: " << message << '\n'; }) {
  last_inserted_ = &frames_.emplace_back();  // id 0: no frame
}

FrameId BufferCore::Impl::idOf(std::string_view name) const { return ids_.find(name); }

// Publishers send the same edges in the same order, cycle after cycle: comparing one name
// with the frame that followed last time is cheaper than hashing it, and on a large tree it
// saves a load from a random place in the name index, which memory then answers.
FrameRecord* BufferCore::Impl::knownChild(std::string_view name, FrameId& id) {
  const FrameId predicted = last_inserted_->next_inserted;
  if (predicted != kNoFrame) {
    FrameRecord& record = frames_[predicted];
    if (detail::sameName(record.name, name)) {
      id = predicted;
      return &record;
    }
  }
  id = idOf(name);
  return id != kNoFrame ? &frames_[id] : nullptr;
}

// Publishers send the same edges in the same order, batch after batch: while one edge is
// stored, what storing the edges two and three later will read starts loading. The samples and
// name of the edge two later are found through its record, which the insert before started
// loading, as this one starts loading the record of the edge three later. On a tree too large
// for the caches, storing an edge otherwise waits on memory for its record, then for its
// samples. Loading for the edge two later rather than the next one took the inserts of
// buffer_core_bench from 146-161 ns to 126-132 on the wide tree, from 119-124 to 92-103 on
// deep_chain and from 121-127 to 95-119 on pr2.
void BufferCore::Impl::prefetchNextInserts(const FrameRecord& record) const {
  const FrameId next = record.next_inserted;
  if (next == kNoFrame) return;
  const FrameId second = frames_[next].next_inserted;
  if (second == kNoFrame) return;
  const FrameRecord& coming = frames_[second];
  detail::prefetchLine(coming.name.data());
  coming.cache.prefetchInsert(comesBackSoon(coming));
  const FrameId after = coming.next_inserted;
  if (after == kNoFrame) return;
  const auto* later = reinterpret_cast<const char*>(&frames_[after]);
  for (std::size_t line = 0; line < kInsertedRecordLines; ++line) {
    detail::prefetchLine(later + alignof(FrameRecord) * line);
  }
}

// An edge stored again within 1,024 samples of the last one (as each edge of a publisher sending
// up to that many is, batch after batch) finds the slot of its next sample loaded: that line is
// new to the cache, and loading it for the edge two later (prefetchNextInserts()) leaves too
// little time where an insert takes 60 ns and memory 165. Up to 1,024 such lines (64 KiB) stay
// in the cache until their turn; an edge coming back later would find its line gone, and the
// load would only have taken memory's time from the inserts before. Against the build before,
// fastest of 7-20 processes taking turns: a listener's batches (listener_receive_bench) stored
// in 48 ns a transform where they took 53-54 on pr2 and deep_chain and 62 on wide, its whole
// receive 96 -> 84 ns on pr2, 88 -> 85 on deep_chain, 95 -> 80 on wide; single inserts of
// buffer_core_bench on wide (333 edges) 64.6-74.6 -> 61.7-63.9, on pr2 and deep_chain (33
// edges) 1-5 % slower, for the instructions this adds; the forest (50,000 edges, no load)
// within its spread.
bool BufferCore::Impl::comesBackSoon(const FrameRecord& record) const {
  constexpr std::uint32_t kSoon = 1024;
  return static_cast<std::uint32_t>(statistics_.inserted) - record.stored_after < kSoon;
}

void BufferCore::Impl::prefetchNextSample(FrameRecord& record) {
  if (comesBackSoon(record)) record.cache.prefetchNextSlot();
  record.stored_after = static_cast<std::uint32_t>(statistics_.inserted) + 1;
}

FrameId BufferCore::Impl::addFrame(std::string_view name) {
  const FrameId existing = idOf(name);
  if (existing != kNoFrame) return existing;
  const std::string_view stored = names_.store(name);
  const auto id = static_cast<FrameId>(frames_.size());
  FrameRecord& record = frames_.emplace_back();
  record.name = stored;
  record.static_top = id;
  ids_.insert(stored, id);
  return id;
}

void BufferCore::Impl::reportCallbackFailure(const std::string& what) {
  std::function<void(const std::string&)> reporter;
  {
    std::lock_guard<std::mutex> guard(reporter_mutex_);
    if (callback_failure_reported_ || !reporter_) return;
    callback_failure_reported_ = true;
    reporter = reporter_;
  }
  reporter("a transformable-request callback threw: " + what +
           " (reported once; the other callbacks still ran)");
}

void BufferCore::Impl::reportOnce(InsertRejection kind, const std::string& message) {
  std::function<void(const std::string&)> reporter;
  {
    std::lock_guard<std::mutex> guard(reporter_mutex_);
    bool& reported = reported_[static_cast<std::size_t>(kind)];
    if (reported || !reporter_) return;
    reported = true;
    reporter = reporter_;
  }
  reporter(printable(message) + " (reported once; later ones are only counted)");
}

namespace {

std::string edgeName(const TransformStamped& t) {
  return "'" + t.parent_frame + "' -> '" + t.child_frame + "' at " + toString(t.stamp);
}

}  // namespace

InsertRejection BufferCore::Impl::store(const TransformStamped& transform, const Transform& value,
                                        bool normalized, const std::string& authority,
                                        bool is_static, std::string& reason) {
  const std::string_view parent = stripLeadingSlash(transform.parent_frame);
  const std::string_view child = stripLeadingSlash(transform.child_frame);
  const std::int64_t stamp = toUtime(transform.stamp);
  // Refuse a sample that is too old before adding any frame, so the refusal changes nothing.
  FrameId known_child = kNoFrame;
  FrameRecord* const known = knownChild(child, known_child);
  if (!is_static && known && known->cache.isTooOld(stamp, cache_time_)) {
    reason = edgeName(transform) + " is older than the history kept: the newest sample is at " +
             toString(fromUtime(known->cache.newestStamp())) + " and the cache time is " +
             toString(Duration(cache_time_));
    return InsertRejection::kOlderThanHistory;
  }
  if (!is_static && known && known->cache.isFullAndOlder(stamp, most_samples_per_edge_)) {
    reason = edgeName(transform) + " already holds its most samples (" +
             std::to_string(most_samples_per_edge_) + "), all newer than this one at " +
             toString(transform.stamp);
    return InsertRejection::kEdgeFull;
  }
  const FrameId child_id = known ? known_child : addFrame(child);
  FrameRecord& record = known ? *known : frames_[child_id];
  prefetchNextInserts(record);
  noteInserted(child_id, record);
  // An edge keeps its parent from one sample to the next: compare before hashing the name.
  const FrameId usual_parent = record.cache.newestParent();
  const FrameId parent_id =
      usual_parent != kNoFrame && detail::sameName(nameOf(usual_parent), parent) ? usual_parent
                                                                                 : addFrame(parent);
  const bool was_static = record.cache.isStatic();
  const bool changed_parent = record.cache.changesParent();
  if (is_static) {
    const bool unchanged =
        was_static && record.cache.staticParent() == parent_id &&
        record.cache.staticTransform().translation == value.translation &&
        record.cache.staticTransform().rotation.coeffs() == value.rotation.coeffs();
    if (!unchanged) {
      if (!was_static || record.cache.staticParent() != parent_id) noteShapeChange(child_id);
      record.cache.setStatic(parent_id, value);
      if (!known && !static_chains_stale_) {
        // A frame new to the buffer has nothing below it: only its own chain is new.
        continueStaticChain(record, frames_[parent_id], value);
      } else {
        static_chains_stale_ = true;
      }
    }
  } else {
    const FrameId parent_before = record.cache.newestParent();
    const detail::InsertOutcome outcome = record.cache.insert(
        detail::EdgeSample{stamp, parent_id, value}, cache_time_, most_samples_per_edge_);
    if (outcome == detail::InsertOutcome::kReplaced) ++statistics_.replaced;
    if (outcome == detail::InsertOutcome::kAddedDroppingOldest) ++statistics_.dropped_for_room;
    prefetchNextSample(record);
    if (was_static) static_chains_stale_ = true;
    if (was_static || record.cache.newestParent() != parent_before) noteShapeChange(child_id);
  }
  if (record.cache.changesParent() && !changed_parent) ++parent_changing_edges_;
  if (!record.cache.changesParent() && changed_parent) --parent_changing_edges_;
  const std::uint32_t authority_id = authorities_.idOf(authority);
  if (record.authority != 0 && record.authority != authority_id) {
    ++record.authority_conflicts;
    ++statistics_.authority_conflicts;
  }
  authorities_.moveEdge(record.authority, authority_id);
  record.authority = authority_id;
  ++statistics_.inserted;
  if (normalized) ++statistics_.normalized;
  return InsertRejection::kCount;
}

void BufferCore::Impl::refreshRootPaths() {
  const bool rebuild = root_paths_stale_ || !root_paths_.canExtendTo(frames_);
  if (rebuild || static_chains_stale_) {
    const detail::RefreshBudget::Clock::time_point start = detail::RefreshBudget::Clock::now();
    if (!refresh_budget_.allows(start)) {
      root_paths_.invalidate();
      return;
    }
    if (static_chains_stale_) computeStaticChains();
    if (rebuild) root_paths_.rebuild(frames_);
    static_chains_stale_ = root_paths_stale_ = false;
    refresh_budget_.spent(start, detail::RefreshBudget::Clock::now());
  }
  if (root_paths_.frameCount() < frames_.size()) root_paths_.extend(frames_);
}

std::size_t BufferCore::Impl::insert(const TransformStamped* transforms, std::size_t count,
                                     const std::string& authority, bool is_static,
                                     std::string* error) {
  if (count == 1) {
    double norm = 1.0;
    std::string reason;
    InsertRejection kind = detail::checkTransform(*transforms, norm, reason);
    Transform normalized_value;
    const bool normalized = norm != 1.0;
    if (normalized) normalized_value = detail::normalizedBy(transforms->transform, norm);
    {
      ExclusiveLock lock(lock_);
      if (kind == InsertRejection::kCount) {
        kind = store(*transforms, normalized ? normalized_value : transforms->transform, normalized,
                     authority, is_static, reason);
        refreshRootPaths();
      }
      if (kind == InsertRejection::kCount) return 1;
      ++statistics_.rejected[static_cast<std::size_t>(kind)];
    }
    reportOnce(kind, "rejected a transform: " + reason);
    if (error) *error = reason;
    return 0;
  }
  struct Refusal {
    InsertRejection kind;
    std::string reason;
  };
  struct Checked {
    bool valid;
    bool normalized;
  };
  // Each transform is checked before the lock is taken. A good one is stored as it came, unless
  // its rotation was scaled to unit length: those values, seldom any, are kept in order. Against a
  // copy of every value, each first set to the identity: storing a batch in listener_receive_bench
  // 65 -> 53 ns a transform on pr2, 61 -> 52 on deep_chain, 67 -> 61 on wide.
  std::vector<Refusal> refusals;
  std::vector<Checked> checked(count);
  std::vector<Transform> normalized_values;
  for (std::size_t i = 0; i < count; ++i) {
    double norm = 1.0;
    std::string reason;
    const InsertRejection kind = detail::checkTransform(transforms[i], norm, reason);
    checked[i] = Checked{kind == InsertRejection::kCount, norm != 1.0};
    if (!checked[i].valid) {
      refusals.push_back({kind, std::move(reason)});
    } else if (checked[i].normalized) {
      normalized_values.push_back(detail::normalizedBy(transforms[i].transform, norm));
    }
  }
  std::size_t stored = 0;
  {
    ExclusiveLock lock(lock_);
    std::size_t next_normalized = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (!checked[i].valid) continue;
      const Transform& value =
          checked[i].normalized ? normalized_values[next_normalized++] : transforms[i].transform;
      std::string reason;
      const InsertRejection kind =
          store(transforms[i], value, checked[i].normalized, authority, is_static, reason);
      if (kind == InsertRejection::kCount) {
        ++stored;
      } else {
        refusals.push_back({kind, std::move(reason)});
      }
    }
    for (const Refusal& refusal : refusals) {
      ++statistics_.rejected[static_cast<std::size_t>(refusal.kind)];
    }
    refreshRootPaths();
  }
  for (const Refusal& refusal : refusals) {
    reportOnce(refusal.kind, "rejected a transform: " + refusal.reason);
  }
  if (error && !refusals.empty()) *error = refusals.front().reason;
  return stored;
}

BufferCore::BufferCore(Duration cache_time) : impl_(std::make_unique<Impl>(cache_time)) {}

BufferCore::~BufferCore() = default;

bool BufferCore::setTransform(const TransformStamped& transform, const std::string& authority,
                              bool is_static, std::string* error) {
  const bool stored = impl_->insert(&transform, 1, authority, is_static, error) == 1;
  if (stored) impl_->notifyDecidedRequests();
  return stored;
}

std::size_t BufferCore::setTransforms(const std::vector<TransformStamped>& transforms,
                                      const std::string& authority, bool is_static,
                                      std::string* error) {
  return setTransforms(transforms.data(), transforms.size(), authority, is_static, error);
}

std::size_t BufferCore::setTransforms(const TransformStamped* transforms, std::size_t count,
                                      const std::string& authority, bool is_static,
                                      std::string* error) {
  if (count == 0) return 0;
  const std::size_t stored = impl_->insert(transforms, count, authority, is_static, error);
  if (stored > 0) impl_->notifyDecidedRequests();
  return stored;
}

void BufferCore::Impl::notifyDecidedRequests() {
  if (!has_requests_.load(std::memory_order_acquire)) return;
  for (auto& notify : collectDecidedRequests()) {
    try {
      notify();
    } catch (const std::exception& e) {
      reportCallbackFailure(e.what());
    } catch (...) {
      reportCallbackFailure("an exception that is not a std::exception");
    }
  }
}

namespace {

std::string lookupWhat(const std::string& target, const std::string& source) {
  return "lookup of '" + source + "' in '" + target + "'";
}

std::string timeTravelWhat(const std::string& target, const std::string& source,
                           const std::string& fixed) {
  return "time-travel lookup of '" + source + "' in '" + target + "' through '" + fixed + "'";
}

[[gnu::noinline]] bool sameUnknownName(const std::string& target, const std::string& source) {
  const std::string_view a = stripLeadingSlash(target);
  return !a.empty() && detail::sameName(a, stripLeadingSlash(source));
}

// tf2 answers a lookup from a frame to itself with identity without checking the frame. Known
// frames compare by id; only two unknown names are compared, which the usual lookup, of two
// known frames, never does: it pays for one comparison of ids here, inline.
inline bool sameFrame(FrameId target_id, FrameId source_id, const std::string& target,
                      const std::string& source) {
  return target_id == source_id && (target_id != kNoFrame || sameUnknownName(target, source));
}

}  // namespace

TransformStamped BufferCore::lookupTransform(const std::string& target, const std::string& source,
                                             TimePoint time) const {
  SharedLock lock(impl_->lock_);
  FrameId target_id = impl_->idOf(stripLeadingSlash(target));
  FrameId source_id = impl_->idOf(stripLeadingSlash(source));
  std::int64_t stamp = toUtime(time);
  if (sameFrame(target_id, source_id, target, source)) {
    if (stamp == 0 && target_id != kNoFrame) impl_->latestCommonTime(target_id, target_id, stamp);
    const std::string name(stripLeadingSlash(target));
    return TransformStamped{fromUtime(stamp), name, name, Transform::identity()};
  }
  // The usual case first, with no failure record to fill in.
  detail::QuickPath path;
  if (target_id != kNoFrame && source_id != kNoFrame &&
      impl_->planQuickLookup(target_id, source_id, stamp, path)) {
    return impl_->quickStamped(target_id, source_id, stamp, path);
  }
  Transform value;
  if (target_id == kNoFrame || source_id == kNoFrame) {
    // Each failure in a variable of its own: see resolvePair().
    const LookupFailure unresolved = impl_->resolvePair(target, source, target_id, source_id);
    impl_->raise(unresolved, lookupWhat(target, source));
  }
  const LookupFailure failure = impl_->lookupByWalk(target_id, source_id, stamp, &value);
  if (failure) impl_->raise(failure, lookupWhat(target, source));
  return impl_->stamped(target_id, source_id, stamp, value);
}

namespace {

bool isForeign(FrameHandle handle, std::size_t frame_count) {
  return !handle || handle.id >= frame_count;
}

}  // namespace

void BufferCore::Impl::checkHandles(FrameHandle target, FrameHandle source) const {
  if (isForeign(target, frames_.size()) || isForeign(source, frames_.size())) {
    throw InvalidArgumentException(
        "lookupTransform: a frame handle is null or not from this buffer");
  }
}

void BufferCore::Impl::walkHandles(FrameHandle target, FrameHandle source, std::int64_t& stamp,
                                   Transform& value) const {
  const LookupFailure failure = lookupByWalk(target.id, source.id, stamp, &value);
  if (failure) {
    raise(failure, lookupWhat(std::string(nameOf(target.id)), std::string(nameOf(source.id))));
  }
}

TransformStamped BufferCore::lookupTransform(FrameHandle target, FrameHandle source,
                                             TimePoint time) const {
  SharedLock lock(impl_->lock_);
  std::int64_t stamp = toUtime(time);
  impl_->checkHandles(target, source);
  // The usual case first, with no failure record to fill in.
  detail::QuickPath path;
  if (target.id != source.id && impl_->planQuickLookup(target.id, source.id, stamp, path)) {
    return impl_->quickStamped(target.id, source.id, stamp, path);
  }
  Transform value;
  impl_->walkHandles(target, source, stamp, value);
  return impl_->stamped(target.id, source.id, stamp, value);
}

namespace {

// Copies `name` into `out` unless it holds it already, as it does when a caller looks up the
// same pair into the same result again.
void assignName(std::string& out, std::string_view name) {
  if (!detail::sameName(out, name)) out.assign(name.data(), name.size());
}

}  // namespace

// As the lookup that returns its result, its value written in place and its names kept when
// they are the same.
void BufferCore::lookupTransform(FrameHandle target, FrameHandle source, TimePoint time,
                                 TransformStamped& result) const {
  SharedLock lock(impl_->lock_);
  std::int64_t stamp = toUtime(time);
  impl_->checkHandles(target, source);
  detail::QuickPath path;
  if (target.id != source.id && impl_->planQuickLookup(target.id, source.id, stamp, path)) {
    // The names first, while the samples the plan asked for load; copied after the value, as
    // the walk's are, they made wide's lookups into a result of buffer_core_bench 85 -> 97 ns.
    assignName(result.parent_frame, impl_->nameOf(target.id));
    assignName(result.child_frame, impl_->nameOf(source.id));
    result.transform = impl_->quickValue(target.id, source.id, stamp, path);
    result.stamp = fromUtime(path.plan.at);
    return;
  }
  impl_->walkHandles(target, source, stamp, result.transform);
  result.stamp = fromUtime(stamp);
  assignName(result.parent_frame, impl_->nameOf(target.id));
  assignName(result.child_frame, impl_->nameOf(source.id));
}

TransformStamped BufferCore::lookupTransform(const std::string& target, TimePoint target_time,
                                             const std::string& source, TimePoint source_time,
                                             const std::string& fixed) const {
  SharedLock lock(impl_->lock_);
  FrameId target_id = impl_->idOf(stripLeadingSlash(target));
  FrameId source_id = impl_->idOf(stripLeadingSlash(source));
  FrameId fixed_id = impl_->idOf(stripLeadingSlash(fixed));
  std::int64_t source_stamp = toUtime(source_time);
  std::int64_t target_stamp = toUtime(target_time);
  Transform target_T_source;
  // The usual case first, with no failure record to fill in.
  if (target_id != kNoFrame && source_id != kNoFrame && fixed_id != kNoFrame &&
      impl_->quickTimeTravel(target_id, target_stamp, source_id, source_stamp, fixed_id,
                             target_T_source)) {
    return impl_->stamped(target_id, source_id, target_stamp, target_T_source);
  }
  if (target_id == kNoFrame || source_id == kNoFrame || fixed_id == kNoFrame) {
    const LookupFailure unresolved =
        impl_->resolveAll(target, source, fixed, target_id, source_id, fixed_id);
    impl_->raise(unresolved, timeTravelWhat(target, source, fixed));
  }
  Transform fixed_T_source;
  Transform target_T_fixed;
  const LookupFailure source_failure =
      impl_->lookup(fixed_id, source_id, source_stamp, &fixed_T_source);
  if (source_failure) impl_->raise(source_failure, lookupWhat(fixed, source));
  const LookupFailure target_failure =
      impl_->lookup(target_id, fixed_id, target_stamp, &target_T_fixed);
  if (target_failure) impl_->raise(target_failure, lookupWhat(target, fixed));
  return impl_->stamped(target_id, source_id, target_stamp,
                        detail::composed(target_T_fixed, fixed_T_source));
}

bool BufferCore::canTransform(const std::string& target, const std::string& source, TimePoint time,
                              std::string* why) const {
  SharedLock lock(impl_->lock_);
  FrameId target_id = impl_->idOf(stripLeadingSlash(target));
  FrameId source_id = impl_->idOf(stripLeadingSlash(source));
  if (sameFrame(target_id, source_id, target, source)) return true;
  if (target_id == kNoFrame || source_id == kNoFrame) {
    const LookupFailure unresolved = impl_->resolvePair(target, source, target_id, source_id);
    if (why) *why = impl_->describe(unresolved, lookupWhat(target, source));
    return false;
  }
  std::int64_t stamp = toUtime(time);
  const LookupFailure failure = impl_->lookup(target_id, source_id, stamp, nullptr);
  if (failure && why) *why = impl_->describe(failure, lookupWhat(target, source));
  return !failure;
}

bool BufferCore::canTransform(FrameHandle target, FrameHandle source, TimePoint time,
                              std::string* why) const {
  SharedLock lock(impl_->lock_);
  const auto frame_count = impl_->frames_.size();
  if (isForeign(target, frame_count) || isForeign(source, frame_count)) {
    if (why) *why = "canTransform: a frame handle is null or not from this buffer";
    return false;
  }
  std::int64_t stamp = toUtime(time);
  const LookupFailure failure = impl_->lookup(target.id, source.id, stamp, nullptr);
  if (failure && why) {
    *why = impl_->describe(failure, lookupWhat(std::string(impl_->nameOf(target.id)),
                                               std::string(impl_->nameOf(source.id))));
  }
  return !failure;
}

bool BufferCore::canTransform(const std::string& target, TimePoint target_time,
                              const std::string& source, TimePoint source_time,
                              const std::string& fixed, std::string* why) const {
  {
    SharedLock lock(impl_->lock_);
    FrameId target_id = kNoFrame;
    FrameId source_id = kNoFrame;
    FrameId fixed_id = kNoFrame;
    const LookupFailure failure =
        impl_->resolveAll(target, source, fixed, target_id, source_id, fixed_id);
    if (failure) {
      if (why) *why = impl_->describe(failure, timeTravelWhat(target, source, fixed));
      return false;
    }
  }
  return canTransform(fixed, source, source_time, why) &&
         canTransform(target, fixed, target_time, why);
}

TimePoint BufferCore::getLatestCommonTime(const std::string& target,
                                          const std::string& source) const {
  SharedLock lock(impl_->lock_);
  FrameId target_id = kNoFrame;
  FrameId source_id = kNoFrame;
  std::int64_t stamp = 0;
  LookupFailure failure = impl_->resolve(target, "target", target_id);
  if (!failure) failure = impl_->resolve(source, "source", source_id);
  if (!failure) failure = impl_->latestCommonTime(target_id, source_id, stamp);
  if (failure) impl_->raise(failure, "latest common time of '" + source + "' and '" + target + "'");
  return fromUtime(stamp);
}

FrameHandle BufferCore::resolveFrame(const std::string& frame) {
  const std::string_view name = stripLeadingSlash(frame);
  if (name.empty()) throw InvalidArgumentException("resolveFrame: frame names must not be empty");
  {
    SharedLock lock(impl_->lock_);
    const FrameId id = impl_->idOf(name);
    if (id != kNoFrame) return FrameHandle{id};
  }
  ExclusiveLock lock(impl_->lock_);
  const FrameHandle handle{impl_->addFrame(name)};
  impl_->refreshRootPaths();
  return handle;
}

FrameHandle BufferCore::findFrame(const std::string& frame) const {
  SharedLock lock(impl_->lock_);
  return FrameHandle{impl_->idOf(stripLeadingSlash(frame))};
}

bool BufferCore::frameExists(const std::string& frame) const { return bool(findFrame(frame)); }

std::size_t BufferCore::frameCount() const {
  SharedLock lock(impl_->lock_);
  return impl_->frames_.size() - 1;
}

bool BufferCore::getParent(const std::string& frame, TimePoint time, std::string& parent) const {
  SharedLock lock(impl_->lock_);
  const FrameId id = impl_->idOf(stripLeadingSlash(frame));
  if (id == kNoFrame) return false;
  const detail::TimeCache& cache = impl_->frames_[id].cache;
  detail::SampleStatus status = detail::SampleStatus::kOk;
  FrameId parent_id = kNoFrame;
  if (time == kLatestTime) {
    parent_id = cache.newestParent();
  } else {
    parent_id = cache.parentAt(toUtime(time), status);
  }
  if (parent_id == kNoFrame || status != detail::SampleStatus::kOk) return false;
  parent.assign(impl_->nameOf(parent_id));
  return true;
}

std::vector<std::string> BufferCore::getAllFrameNames() const {
  SharedLock lock(impl_->lock_);
  std::vector<std::string> names;
  names.reserve(impl_->frames_.size() - 1);
  for (std::size_t id = 1; id < impl_->frames_.size(); ++id) {
    names.emplace_back(impl_->frames_[id].name);
  }
  return names;
}

std::vector<std::string> BufferCore::getFrameChain(const std::string& target,
                                                   const std::string& source,
                                                   TimePoint time) const {
  SharedLock lock(impl_->lock_);
  FrameId target_id = kNoFrame;
  FrameId source_id = kNoFrame;
  LookupFailure failure = impl_->resolve(target, "target", target_id);
  if (!failure) failure = impl_->resolve(source, "source", source_id);
  std::vector<PathEdge> up_from_source;
  std::vector<PathEdge> up_from_target;
  FrameId ancestor = kNoFrame;
  std::int64_t stamp = toUtime(time);
  if (!failure && stamp == 0) failure = impl_->latestCommonTime(target_id, source_id, stamp);
  if (!failure) {
    failure = impl_->walk(target_id, source_id, stamp, up_from_source, up_from_target, &ancestor);
  }
  if (failure) impl_->raise(failure, "frame chain from '" + source + "' to '" + target + "'");
  std::vector<std::string> chain;
  for (const PathEdge& edge : up_from_source) chain.emplace_back(impl_->nameOf(edge.child));
  chain.emplace_back(impl_->nameOf(ancestor));
  for (auto edge = up_from_target.rbegin(); edge != up_from_target.rend(); ++edge) {
    chain.emplace_back(impl_->nameOf(edge->child));
  }
  return chain;
}

void BufferCore::clear() {
  ExclusiveLock lock(impl_->lock_);
  for (FrameRecord& frame : impl_->frames_) frame.cache.clearHistory();
  impl_->parent_changing_edges_ = 0;
  impl_->root_paths_stale_ = true;
  impl_->refreshRootPaths();
}

std::size_t BufferCore::clearAuthority(const std::string& authority) {
  ExclusiveLock lock(impl_->lock_);
  const std::uint32_t id = impl_->authorities_.find(authority);
  if (id == 0) return 0;
  std::size_t cleared = 0;
  for (FrameRecord& frame : impl_->frames_) {
    if (frame.authority != id || frame.cache.isStatic() || frame.cache.empty()) continue;
    if (frame.cache.changesParent()) --impl_->parent_changing_edges_;
    frame.cache.clearHistory();
    ++cleared;
  }
  if (cleared > 0) {
    impl_->root_paths_stale_ = true;
    impl_->refreshRootPaths();
  }
  return cleared;
}

Duration BufferCore::cacheTime() const { return Duration(impl_->cache_time_); }

void BufferCore::setMostSamplesPerEdge(std::size_t most) {
  if (most < 2) throw std::invalid_argument("setMostSamplesPerEdge: an edge needs at least 2");
  ExclusiveLock lock(impl_->lock_);
  impl_->most_samples_per_edge_ = most;
}

std::size_t BufferCore::mostSamplesPerEdge() const {
  SharedLock lock(impl_->lock_);
  return impl_->most_samples_per_edge_;
}

void BufferCore::setMaxInterpolationGap(Duration gap) {
  if (gap < Duration::zero()) {
    throw std::invalid_argument("setMaxInterpolationGap: the gap must not be negative");
  }
  ExclusiveLock lock(impl_->lock_);
  impl_->max_gap_ = gap.count();
}

Duration BufferCore::maxInterpolationGap() const {
  SharedLock lock(impl_->lock_);
  return Duration(impl_->max_gap_);
}

InsertStatistics BufferCore::statistics() const {
  SharedLock lock(impl_->lock_);
  return impl_->statistics_;
}

void BufferCore::setErrorReporter(std::function<void(const std::string& message)> reporter) {
  std::lock_guard<std::mutex> guard(impl_->reporter_mutex_);
  impl_->reporter_ = std::move(reporter);
}

}  // namespace lcmtf
