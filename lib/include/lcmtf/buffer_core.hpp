#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lcmtf/edge_description.hpp"
#include "lcmtf/exceptions.hpp"
#include "lcmtf/insert_statistics.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf/transform_stamped.hpp"
#include "lcmtf/velocity.hpp"

namespace lcmtf {

/// A frame name resolved once by BufferCore::resolveFrame; lookups by handle skip hashing.
/// Valid for the life of the buffer it came from (clear() keeps frames). Zero means no frame.
struct FrameHandle {
  std::uint32_t id = 0;
  explicit operator bool() const { return id != 0; }
  friend bool operator==(FrameHandle a, FrameHandle b) { return a.id == b.id; }
  friend bool operator!=(FrameHandle a, FrameHandle b) { return a.id != b.id; }
};

/// Identifies a pending transformable request; 0 means "already transformable, none made".
using TransformableRequestHandle = std::uint64_t;

/// How a transformable request ended.
enum class TransformableResult { kAvailable, kFailure };

/// Called once per request, outside the buffer's lock, from the setTransform that decided it.
using TransformableCallback =
    std::function<void(TransformableRequestHandle handle, const std::string& target,
                       const std::string& source, TimePoint time, TransformableResult result)>;

/// The frame tree over time: edges with their recent history and static edges, and lookups
/// between any two frames at any stored time. No I/O, no threads, no waiting. Any number of
/// threads may look up while others insert.
class BufferCore {
 public:
  static constexpr Duration kDefaultCacheTime = std::chrono::seconds(10);

  /// `cache_time`: how much history each dynamic edge keeps behind its newest sample.
  explicit BufferCore(Duration cache_time = kDefaultCacheTime);
  ~BufferCore();
  BufferCore(const BufferCore&) = delete;
  BufferCore& operator=(const BufferCore&) = delete;

  /// Stores parent_T_child at its stamp (or for all time when `is_static`). Bad input changes
  /// nothing: returns false, counts it, and says why in `error` when given.
  bool setTransform(const TransformStamped& transform, const std::string& authority,
                    bool is_static = false, std::string* error = nullptr);
  /// setTransform for a batch under one lock, deciding pending requests once at the end;
  /// returns how many were stored (`error` gets the first refusal's reason).
  std::size_t setTransforms(const std::vector<TransformStamped>& transforms,
                            const std::string& authority, bool is_static = false,
                            std::string* error = nullptr);
  /// setTransforms for the `count` transforms from `transforms` on.
  std::size_t setTransforms(const TransformStamped* transforms, std::size_t count,
                            const std::string& authority, bool is_static = false,
                            std::string* error = nullptr);

  /// target_T_source at `time` (kLatestTime: the latest time every edge on the path has data).
  /// Throws LookupException, ConnectivityException, ExtrapolationException,
  /// InvalidArgumentException.
  TransformStamped lookupTransform(const std::string& target, const std::string& source,
                                   TimePoint time) const;
  TransformStamped lookupTransform(FrameHandle target, FrameHandle source, TimePoint time) const;
  /// The same into `result`, whose strings keep their storage: no allocation once warm.
  void lookupTransform(FrameHandle target, FrameHandle source, TimePoint time,
                       TransformStamped& result) const;
  /// Time travel: source at source_time into `fixed`, then `fixed` at target_time into target.
  TransformStamped lookupTransform(const std::string& target, TimePoint target_time,
                                   const std::string& source, TimePoint source_time,
                                   const std::string& fixed) const;

  /// Whether the matching lookupTransform would succeed; never throws; says why not in `why`.
  bool canTransform(const std::string& target, const std::string& source, TimePoint time,
                    std::string* why = nullptr) const;
  bool canTransform(FrameHandle target, FrameHandle source, TimePoint time,
                    std::string* why = nullptr) const;
  bool canTransform(const std::string& target, TimePoint target_time, const std::string& source,
                    TimePoint source_time, const std::string& fixed,
                    std::string* why = nullptr) const;

  /// The latest time at which every edge between the two frames has data (zero if all static).
  TimePoint getLatestCommonTime(const std::string& target, const std::string& source) const;

  /// Velocity of `tracking` relative to `observation`, expressed in `observation`, by central
  /// difference over `averaging_interval` around `time`, clipped to the data available (then
  /// shorter, and no longer centred on `time`, which is the stamp given back).
  Velocity lookupVelocity(const std::string& tracking, const std::string& observation,
                          TimePoint time, Duration averaging_interval) const;

  /// A handle for `frame`, creating the frame if it does not exist yet.
  FrameHandle resolveFrame(const std::string& frame);
  /// The handle of an existing frame, or a null handle.
  FrameHandle findFrame(const std::string& frame) const;
  bool frameExists(const std::string& frame) const;
  /// How many frames the buffer knows, parents included.
  std::size_t frameCount() const;
  /// The parent of `frame` at `time`; false when it has none there.
  bool getParent(const std::string& frame, TimePoint time, std::string& parent) const;
  /// Every frame ever seen, parents included, in the order they appeared.
  std::vector<std::string> getAllFrameNames() const;
  /// The frames from `source` up to the common ancestor and down to `target`, at `time`.
  std::vector<std::string> getFrameChain(const std::string& target, const std::string& source,
                                         TimePoint time = kLatestTime) const;
  /// Every edge held, in the order its child frame appeared.
  std::vector<EdgeDescription> describeEdges() const;
  /// Per frame: parent, authority, average rate, samples held, oldest and newest stamp.
  std::string allFramesAsYaml() const;
  /// The tree as a Graphviz digraph, edges labelled with authority, rate and history.
  std::string allFramesAsDot() const;

  /// Calls `callback` once `target` and `source` can be transformed at `time`, or with
  /// kFailure once `time` has fallen out of the cache window. Returns 0, without calling,
  /// when they can be transformed already.
  TransformableRequestHandle addTransformableRequest(TransformableCallback callback,
                                                     const std::string& target,
                                                     const std::string& source,
                                                     TimePoint time) const;
  void cancelTransformableRequest(TransformableRequestHandle handle) const;

  /// Drops all dynamic history; frames, static edges, statistics and requests stay.
  void clear();
  /// Drops the dynamic history of the edges whose newest sample came from `authority` (a
  /// sender that restarted, or a log replayed again); returns how many edges it cleared.
  std::size_t clearAuthority(const std::string& authority);

  Duration cacheTime() const;
  /// At most this many samples are kept per edge, whatever rate a peer sends at: beyond it the
  /// oldest makes room, and a sample older than all kept is refused (kEdgeFull). The default
  /// covers the cache time at 1.2 kHz (12,000 samples for 10 s), and at least 64.
  void setMostSamplesPerEdge(std::size_t most);
  std::size_t mostSamplesPerEdge() const;
  /// A lookup at a time between two samples of an edge further apart than `gap` fails with
  /// InterpolationGapException instead of interpolating across the hole (lost messages, a
  /// stalled sender). Zero, the default as in tf2, sets no limit. Lookups are slower with a
  /// limit set.
  void setMaxInterpolationGap(Duration gap);
  Duration maxInterpolationGap() const;
  InsertStatistics statistics() const;
  /// Where each first rejection of a kind is reported (default: a line on stderr).
  void setErrorReporter(std::function<void(const std::string& message)> reporter);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lcmtf
