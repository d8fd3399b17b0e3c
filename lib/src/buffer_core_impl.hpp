#pragma once

#include <algorithm>
#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "authority_table.hpp"
#include "frame_name_index.hpp"
#include "frame_record.hpp"
#include "lcmtf/buffer_core.hpp"
#include "lcmtf/frame_name.hpp"
#include "lookup_mode.hpp"
#include "name_arena.hpp"
#include "quick_path.hpp"
#include "read_mostly_lock.hpp"
#include "refresh_budget.hpp"
#include "root_paths.hpp"
#include "time_cache.hpp"

namespace lcmtf {

/// How lookups and the other readers hold the buffer's lock, and how inserts do.
using SharedLock = detail::ReadMostlyLock::SharedHold;
using ExclusiveLock = std::unique_lock<detail::ReadMostlyLock>;

/// The newest stamp at which every dynamic edge added so far has data, once there is one: the
/// latest common time of a path (0 when it has no dynamic edge). As in tf, an edge whose newest
/// sample is stamped 0 (time 0 also asks for the latest) sets no bound.
struct CommonNewest {
  std::int64_t stamp = 0;
  bool any_dynamic = false;

  // Without branches: which edge of a path sets the bound follows no pattern a processor could
  // learn (2 % off pr2's latest-time lookups in buffer_core_bench).
  void add(std::int64_t newest) {
    const bool bounds = newest != 0;
    stamp = bounds && (!any_dynamic || newest < stamp) ? newest : stamp;
    any_dynamic = any_dynamic || bounds;
  }
};

/// An edge on the path a walk takes.
struct PathEdge {
  FrameId child = kNoFrame;
  FrameId parent = kNoFrame;
  detail::SampleStatus status = detail::SampleStatus::kOk;
  const Transform* fixed = nullptr;  // the value of a static edge
  bool isDynamic() const { return fixed == nullptr; }
};

/// Why a lookup failed, kept as plain data so a successful lookup pays nothing for it and
/// canTransform pays for no message it does not print.
struct LookupFailure {
  enum class Kind {
    kNone,
    kInvalidName,
    kUnknownFrame,
    kNotConnected,
    kLoop,
    kPast,
    kFuture,
    kGap
  };
  Kind kind = Kind::kNone;
  const std::string* frame = nullptr;  // the bad or unknown name, as the caller gave it
  const char* role = "";               // "target", "source", "fixed"
  FrameId target = kNoFrame;
  FrameId source = kNoFrame;
  FrameId edge_child = kNoFrame;  // extrapolation or gap: the edge (child -> its parent)
  FrameId edge_parent = kNoFrame;
  FrameId loop_start = kNoFrame;  // a frame whose ancestors loop
  std::int64_t requested = 0;
  std::int64_t oldest = 0;  // extrapolation: the edge's oldest and newest samples; gap: the two
  std::int64_t newest = 0;  // samples around the requested time
  explicit operator bool() const { return kind != Kind::kNone; }
};

/// The pending request of addTransformableRequest.
struct TransformableRequest {
  TransformableCallback callback;
  std::string target;
  std::string source;
  TimePoint time;
  FrameId target_id = kNoFrame;  // once the frames exist
  FrameId source_id = kNoFrame;
};

class BufferCore::Impl {
 public:
  explicit Impl(Duration cache_time);

  // All of these expect lock_ held (shared is enough unless they say they write).
  FrameId idOf(std::string_view name) const;
  FrameId addFrame(std::string_view name);  // exclusive lock
  /// idOf() for the child of an edge being inserted, trying first the frame whose edge came
  /// after the last one inserted the time before; the frame's record, or null when unknown.
  FrameRecord* knownChild(std::string_view name, FrameId& id);
  /// Notes that `child`'s edge, whose record is `record`, was inserted after the last one
  /// (exclusive lock).
  void noteInserted(FrameId child, FrameRecord& record) {
    last_inserted_->next_inserted = child;
    last_inserted_ = &record;
  }
  /// Starts loading what storing the edges that came after `record`'s the time before will
  /// read (see the definition).
  void prefetchNextInserts(const FrameRecord& record) const;
  /// Just after a dynamic sample of `record`'s edge is stored: starts loading the slot of the
  /// edge's next sample when that is likely to stay in the cache until then (see the
  /// definition).
  void prefetchNextSample(FrameRecord& record);
  /// Whether `record`'s edge was last stored within the last 1,024 samples the buffer stored:
  /// a publisher of up to that many edges sends it again before its next slot leaves the cache.
  bool comesBackSoon(const FrameRecord& record) const;
  std::string_view nameOf(FrameId id) const { return ids_.nameOf(id); }
  std::string quoted(FrameId id) const { return "'" + std::string(nameOf(id)) + "'"; }

  /// target_T_source at `stamp` (0: the latest common time, written back) into `value` when
  /// given, or why not.
  /// Tries quickLookup(), then lookupByWalk(): two ways of planning the same path, sampled
  /// and composed alike.
  LookupFailure lookup(FrameId target, FrameId source, std::int64_t& stamp, Transform* value) const;
  /// lookup() by the walk alone, for callers that have tried quickLookup(). At time 0 it finds
  /// the latest common time in the tree as of each edge's newest sample, then walks the tree
  /// as it was at that time, as tf does.
  LookupFailure lookupByWalk(FrameId target, FrameId source, std::int64_t& stamp,
                             Transform* value) const;
  /// Aborts with both answers unless lookupByWalk() at `requested` gives `answered` and, when
  /// given, the `quick` value, to rounding: every quick answer is checked so in the sanitizer
  /// builds. `magnitude` is the sum of the translations the quick answer was composed from,
  /// whose rounding errors it carries.
  void crossCheck(FrameId target, FrameId source, std::int64_t requested, std::int64_t answered,
                  const Transform* quick, double magnitude) const;
  /// Throws unless both handles are of this buffer's frames.
  void checkHandles(FrameHandle target, FrameHandle source) const;
  /// The lookup between two handles by the walk alone, for callers that have tried the root
  /// paths; throws when it fails.
  void walkHandles(FrameHandle target, FrameHandle source, std::int64_t& stamp,
                   Transform& value) const;
  /// The stamped result of a lookup that succeeded.
  TransformStamped stamped(FrameId target, FrameId source, std::int64_t stamp,
                           const Transform& value) const {
    return TransformStamped{fromUtime(stamp), std::string(nameOf(target)),
                            std::string(nameOf(source)), value};
  }
  /// lookup() by the root paths, for the usual case. False when that cannot answer, or may
  /// not answer as the walk would: a frame without a path, an edge on the way whose history
  /// changes parent, or any failure; then the walk must, and `stamp` is left as it was.
  bool quickLookup(FrameId target, FrameId source, std::int64_t& stamp, Transform* value) const;
  /// quickLookup() with a value, in a frame of its own: the rooms for sampling the path take
  /// 11 KiB of the stack, which a lookup without a value (canTransform(), the latest common
  /// time) then leaves alone.
  [[gnu::noinline]] bool quickLookupInto(FrameId target, FrameId source, std::int64_t& stamp,
                                         Transform& value) const;
  /// quickLookup() in two halves, for callers with work to do while the samples load: the
  /// plan, whose `at` is the stamp of the answer, with its samples taken and their loads
  /// started, then its value.
  bool planQuickLookup(FrameId target, FrameId source, std::int64_t stamp,
                       detail::QuickPath& path) const;
  /// Whether lookups may take the root paths: they are on (lookup_mode.hpp), and no gap
  /// between samples is refused, which only the walk checks.
  bool quickLookupsApply() const { return detail::quickLookupsEnabled() && max_gap_ == 0; }
  /// The plan of a quick lookup into `path`, starting the loads of its samples when `prefetch`,
  /// and sampling at the latest common time into `sampling` (the QuickPath that `path` is)
  /// unless null; false when quick lookups are off or cannot answer.
  bool planQuickly(FrameId target, FrameId source, std::int64_t stamp, bool prefetch,
                   detail::QuickPlan& path, detail::QuickPath* sampling) const;
  Transform quickValue(FrameId target, FrameId source, std::int64_t stamp,
                       detail::QuickPath& path) const;
  /// The stamped result of `path`, planned by planQuickLookup(), built where the caller
  /// receives it: its names are copied while the samples the plan asked for load (a braced
  /// list keeps the order written) and its value is written in place. 27 instructions fewer a
  /// lookup than filling a value and copying it in, 2 % of a deepest lookup on the wide tree
  /// of buffer_core_bench.
  TransformStamped quickStamped(FrameId target, FrameId source, std::int64_t stamp,
                                detail::QuickPath& path) const {
    return TransformStamped{fromUtime(path.plan.at), std::string(nameOf(target)),
                            std::string(nameOf(source)), quickValue(target, source, stamp, path)};
  }
  /// The time-travel lookup by the root paths: `source` at `source_stamp` into `fixed`, then
  /// `fixed` at `target_stamp` into `target`, sampled and interpolated together. False, with
  /// nothing written, when quickLookup() could not answer either half, or `fixed` is one of
  /// the others.
  bool quickTimeTravel(FrameId target, std::int64_t& target_stamp, FrameId source,
                       std::int64_t& source_stamp, FrameId fixed, Transform& value) const;
  LookupFailure latestCommonTime(FrameId target, FrameId source, std::int64_t& stamp) const;
  /// A gap wider than max_gap_ between the samples around `stamp` on the walked edges.
  LookupFailure findGap(const std::vector<PathEdge>& edges, std::int64_t stamp) const;
  /// latestCommonTime() of two different frames by the walk alone.
  LookupFailure latestCommonTimeByWalk(FrameId target, FrameId source, std::int64_t& stamp) const;
  /// The edges from each frame up to their common ancestor at `stamp` (0: the tree as of each
  /// edge's newest sample), one by one as tf walks them, each with data at `stamp`. Lookups
  /// the root paths cannot answer take this way, which holds in any tree, loops and changing
  /// parents included. Frames whose trees do not meet are not connected, even where an edge
  /// on the way lacks data too (its parent then taken from its nearest sample).
  LookupFailure walk(FrameId target, FrameId source, std::int64_t stamp,
                     std::vector<PathEdge>& source_edges, std::vector<PathEdge>& target_edges,
                     FrameId* ancestor) const;
  /// walk() once: through the edges without data at `stamp`, or, as tf does, with the
  /// source's climb ending below the first one and the target's failing on it.
  LookupFailure climb(FrameId target, FrameId source, std::int64_t stamp, bool through_missing_data,
                      std::vector<PathEdge>& source_edges, std::vector<PathEdge>& target_edges,
                      FrameId* ancestor) const;
  /// Recomputes every frame's static_top and the chain up to it after a static edge changed
  /// (exclusive lock).
  void computeStaticChains();
  /// Brings the static chains and the root paths up to date (exclusive lock): rebuilt when a
  /// frame they know has changed its edge, extended when only new frames have come. A rebuild
  /// the budget puts off leaves the paths unusable, and lookups walk, until a later call.
  void refreshRootPaths();
  /// Notes that `frame`'s edge has changed the tree's shape: a frame the root paths know
  /// means rebuilding them; a newer one gets its path when they are extended.
  void noteShapeChange(FrameId frame) {
    if (frame < root_paths_.frameCount()) root_paths_stale_ = true;
  }
  /// The stamps [oldest, newest] at which every dynamic edge between the frames has data, with
  /// the tree as it stands at its newest samples; both zero when every edge is static.
  LookupFailure commonTimeRange(FrameId target, FrameId source, std::int64_t& oldest,
                                std::int64_t& newest) const;
  LookupFailure resolve(const std::string& name, const char* role, FrameId& id) const;
  /// The two frames of a lookup, each named by its role when unknown.
  LookupFailure resolvePair(const std::string& target, const std::string& source,
                            FrameId& target_id, FrameId& source_id) const;
  /// The three frames of a time-travel lookup, each named by its role when unknown.
  LookupFailure resolveAll(const std::string& target, const std::string& source,
                           const std::string& fixed, FrameId& target_id, FrameId& source_id,
                           FrameId& fixed_id) const;
  std::string describe(const LookupFailure& failure, const std::string& what) const;
  [[noreturn]] void raise(const LookupFailure& failure, const std::string& what) const;

  /// Stores a validated transform (exclusive lock); kCount when stored.
  InsertRejection store(const TransformStamped& transform, const Transform& value, bool normalized,
                        const std::string& authority, bool is_static, std::string& reason);
  /// Validates and stores `count` transforms under one lock; returns how many were stored.
  std::size_t insert(const TransformStamped* transforms, std::size_t count,
                     const std::string& authority, bool is_static, std::string* error);
  /// Runs the callbacks of the requests decided by the data now stored (no lock held).
  void notifyDecidedRequests();
  void reportOnce(InsertRejection kind, const std::string& message);
  void reportCallbackFailure(const std::string& what);

  /// Requests decided by the data now stored; call without lock_ and run them afterwards.
  std::vector<std::function<void()>> collectDecidedRequests();

  mutable detail::ReadMostlyLock lock_;
  const std::int64_t cache_time_;
  std::size_t most_samples_per_edge_;
  // Lookups between two samples further apart than this fail (0: no limit). While there is a
  // limit, every lookup takes the walk, which checks it.
  std::int64_t max_gap_ = 0;
  detail::NameArena names_;  // stable storage behind FrameRecord::name
  FrameTable frames_;
  detail::FrameNameIndex ids_;
  // The record of the child of the edge inserted last (that of id 0 before any): the records
  // never move, and an insert then finds it without working out where id's record is.
  FrameRecord* last_inserted_ = nullptr;
  RootPaths root_paths_;
  bool root_paths_stale_ = false;
  // A static edge has changed: the chains are recomputed with the root paths.
  bool static_chains_stale_ = false;
  detail::RefreshBudget refresh_budget_;
  // How many dynamic edges hold samples with more than one parent: while there are none, the
  // tree is the same at every time, above the point where two paths meet as well.
  std::size_t parent_changing_edges_ = 0;
  detail::AuthorityTable authorities_;
  InsertStatistics statistics_;

  std::mutex reporter_mutex_;
  std::function<void(const std::string&)> reporter_;
  std::array<bool, static_cast<std::size_t>(InsertRejection::kCount)> reported_{};
  bool callback_failure_reported_ = false;

  std::mutex requests_mutex_;
  std::map<TransformableRequestHandle, TransformableRequest> requests_;
  TransformableRequestHandle next_request_ = 1;
  std::atomic<bool> has_requests_{false};
};

/// The frames of the loop above `start` in the tree at `stamp` (0: as of the newest samples).
std::vector<FrameId> findLoop(const FrameTable& frames, FrameId start, std::int64_t stamp,
                              bool latest);

/// One leading '/' is not part of a frame's name.
inline std::string_view stripLeadingSlash(std::string_view name) {
  return canonicalFrameName(name);
}

}  // namespace lcmtf
