// Walking the frame tree: from both frames up to their common ancestor, then composing.
#include <algorithm>

#include "batch_interpolation.hpp"
#include "buffer_core_impl.hpp"
#include "path_product.hpp"

namespace lcmtf {

namespace {

using detail::SampleStatus;

// Per-thread scratch, so that a lookup allocates nothing once warm.
struct WalkScratch {
  std::vector<std::uint64_t> visit_epoch;
  std::vector<std::uint32_t> visit_index;
  std::uint64_t epoch = 0;
  std::vector<PathEdge> source_edges;
  std::vector<PathEdge> target_edges;
  std::vector<Transform> interpolated;
  std::vector<detail::InterpolationTask> tasks;
  std::vector<const Transform*> values;
};
__attribute__((tls_model("initial-exec"))) thread_local WalkScratch scratch;

}  // namespace

// Walks up from `start` for more steps than there are frames to find the frames of the loop.
std::vector<FrameId> findLoop(const std::vector<FrameRecord>& frames, FrameId start,
                              std::int64_t stamp, bool latest) {
  std::vector<FrameId> visited;
  FrameId frame = start;
  while (frame != kNoFrame && visited.size() <= 2 * frames.size()) {
    const auto seen = std::find(visited.begin(), visited.end(), frame);
    if (seen != visited.end()) return std::vector<FrameId>(seen, visited.end());
    visited.push_back(frame);
    const detail::TimeCache& cache = frames[frame].cache;
    SampleStatus status;
    frame = latest ? cache.newestParent() : cache.parentAt(stamp, status);
  }
  return visited;
}

namespace {

// The edge up from `frame`, as it was at `stamp` (0: as of its newest sample); its parent is
// kNoFrame at a root.
void stepUp(const std::vector<FrameRecord>& frames, FrameId frame, std::int64_t stamp,
            PathEdge& edge) {
  const detail::TimeCache& cache = frames[frame].cache;
  edge.child = frame;
  edge.status = SampleStatus::kOk;
  if (cache.isStatic()) {
    edge.fixed = &cache.staticValue().transform;
    edge.parent = cache.staticValue().parent;
  } else {
    edge.fixed = nullptr;
    edge.parent = stamp == 0 ? cache.newestParent() : cache.parentAt(stamp, edge.status);
  }
}

// The path's value from each edge's: the dynamic edges between two samples are interpolated
// together, then all are composed.
Transform pathValue(WalkScratch& s) {
  std::size_t between = 0;
  for (const auto* edges : {&s.source_edges, &s.target_edges}) {
    for (const PathEdge& edge : *edges) between += edge.isDynamic() && edge.span.newer ? 1 : 0;
  }
  if (s.interpolated.size() < between) s.interpolated.resize(between);
  s.tasks.clear();
  s.values.clear();
  for (auto* edges : {&s.source_edges, &s.target_edges}) {
    for (PathEdge& edge : *edges) {
      if (!edge.isDynamic()) {
        s.values.push_back(edge.fixed);
      } else if (!edge.span.newer) {
        s.values.push_back(edge.span.older);
      } else {
        Transform* out = &s.interpolated[s.tasks.size()];
        s.tasks.push_back(
            {edge.span.older, edge.span.newer, edge.span.ratio, out, edge.span.arc_squared});
        s.values.push_back(out);
      }
    }
  }
  detail::interpolateBatch(s.tasks.data(), s.tasks.size());
  Transform target_T_source;
  detail::pathProduct(s.values.data(), s.source_edges.size(),
                      s.values.data() + s.source_edges.size(), s.target_edges.size(),
                      target_T_source);
  return target_T_source;
}

// A dynamic edge without data at `stamp`, as a failure.
LookupFailure missingData(const std::vector<FrameRecord>& frames, const PathEdge& edge,
                          std::int64_t stamp) {
  const detail::TimeCache& cache = frames[edge.child].cache;
  LookupFailure failure;
  failure.kind = edge.status == SampleStatus::kPast ? LookupFailure::Kind::kPast
                                                    : LookupFailure::Kind::kFuture;
  failure.edge_child = edge.child;
  failure.edge_parent = edge.parent;
  failure.requested = stamp;
  failure.oldest = cache.oldestStamp();
  failure.newest = cache.newestStamp();
  return failure;
}

// The first dynamic edge without data at `stamp` as a failure; fills the spans otherwise,
// unless `check_only` (the walk at `stamp` has found whether each edge has data there).
// A span whose parent is not the one the walk used means the tree was different at `stamp`.
LookupFailure sampleEdges(const std::vector<FrameRecord>& frames, std::vector<PathEdge>& edges,
                          std::int64_t stamp, bool* parent_changed, bool check_only = false) {
  for (PathEdge& edge : edges) {
    if (!edge.isDynamic()) continue;
    const detail::TimeCache& cache = frames[edge.child].cache;
    if (edge.status == SampleStatus::kOk && check_only) continue;
    if (edge.status == SampleStatus::kOk) {
      edge.status = cache.find(stamp, edge.span);
    }
    if (edge.status == SampleStatus::kOk) {
      if (parent_changed && edge.span.parent != edge.parent) *parent_changed = true;
      continue;
    }
    return missingData(frames, edge, stamp);
  }
  return {};
}

// The newest stamp every dynamic edge of the walk has data at; 0 when all are static.
std::int64_t commonNewest(const std::vector<FrameRecord>& frames,
                          const std::vector<PathEdge>& source_edges,
                          const std::vector<PathEdge>& target_edges) {
  CommonNewest common;
  for (const auto* edges : {&source_edges, &target_edges}) {
    for (const PathEdge& edge : *edges) {
      if (edge.isDynamic()) common.add(frames[edge.child].cache.newestStamp());
    }
  }
  return common.stamp;
}

}  // namespace

LookupFailure BufferCore::Impl::walk(FrameId target, FrameId source, std::int64_t stamp,
                                     std::vector<PathEdge>& source_edges,
                                     std::vector<PathEdge>& target_edges, FrameId* ancestor) const {
  const LookupFailure failure =
      climb(target, source, stamp, false, source_edges, target_edges, ancestor);
  if (failure.kind != LookupFailure::Kind::kPast && failure.kind != LookupFailure::Kind::kFuture) {
    return failure;
  }
  // Frames whose trees do not meet even through the edges without data are not connected,
  // which says more than the missing data does.
  const LookupFailure through =
      climb(target, source, stamp, true, source_edges, target_edges, ancestor);
  return through.kind == LookupFailure::Kind::kNotConnected ? through : failure;
}

LookupFailure BufferCore::Impl::climb(FrameId target, FrameId source, std::int64_t stamp,
                                      bool through_missing_data,
                                      std::vector<PathEdge>& source_edges,
                                      std::vector<PathEdge>& target_edges,
                                      FrameId* ancestor) const {
  WalkScratch& s = scratch;
  if (s.visit_epoch.size() < frames_.size()) {
    s.visit_epoch.resize(frames_.size(), 0);
    s.visit_index.resize(frames_.size(), 0);
  }
  const std::uint64_t epoch = ++s.epoch;
  source_edges.clear();
  target_edges.clear();
  const std::size_t max_depth = frames_.size();
  auto loopFailure = [&](FrameId from) {
    LookupFailure failure;
    failure.kind = LookupFailure::Kind::kLoop;
    failure.target = target;
    failure.source = source;
    failure.requested = stamp;
    failure.loop_start = from;
    return failure;
  };

  // An edge with samples, none of them at `stamp`, unless told to go through those.
  auto stopsAt = [&](const PathEdge& edge) {
    return edge.parent != kNoFrame && edge.status != SampleStatus::kOk && !through_missing_data;
  };

  // Every frame the source's walk reaches is marked with its place in the walk; the target's
  // walk stops at the first marked frame, their common ancestor. Unless told to go through,
  // the source's walk ends below an edge without data at `stamp` (the target's walk may still
  // meet it there), and the target's fails on one.
  FrameId frame = source;
  FrameId source_root = source;
  LookupFailure source_stopped;
  for (std::size_t depth = 0;; ++depth) {
    if (depth > max_depth) return loopFailure(source);
    s.visit_epoch[frame] = epoch;
    s.visit_index[frame] = static_cast<std::uint32_t>(source_edges.size());
    if (frame == target) {
      *ancestor = target;
      return {};
    }
    // Filled in place: a copy of a freshly written edge would stall on store forwarding.
    PathEdge& edge = source_edges.emplace_back();
    stepUp(frames_, frame, stamp, edge);
    const bool missing_data = stopsAt(edge);
    if (edge.parent == kNoFrame || missing_data) {
      if (missing_data) source_stopped = missingData(frames_, edge, stamp);
      source_edges.pop_back();
      source_root = frame;
      break;
    }
    frame = edge.parent;
  }

  frame = target;
  for (std::size_t depth = 0;; ++depth) {
    if (depth > max_depth) return loopFailure(target);
    if (s.visit_epoch[frame] == epoch) {
      source_edges.resize(s.visit_index[frame]);
      *ancestor = frame;
      return {};
    }
    PathEdge& edge = target_edges.emplace_back();
    stepUp(frames_, frame, stamp, edge);
    if (stopsAt(edge)) return missingData(frames_, edge, stamp);
    if (edge.parent == kNoFrame) {
      target_edges.pop_back();
      if (source_stopped) return source_stopped;
      LookupFailure failure;
      failure.kind = LookupFailure::Kind::kNotConnected;
      failure.target = target;
      failure.source = source;
      failure.requested = stamp;
      failure.edge_child = source_root;  // the two roots
      failure.edge_parent = frame;
      return failure;
    }
    frame = edge.parent;
  }
}

LookupFailure BufferCore::Impl::latestCommonTime(FrameId target, FrameId source,
                                                 std::int64_t& stamp) const {
  stamp = 0;
  if (target == source) {
    const detail::TimeCache& cache = frames_[target].cache;
    if (!cache.empty() && !cache.isStatic()) stamp = cache.newestStamp();
    return {};
  }
  if (quickLookup(target, source, stamp, nullptr)) return {};
  std::vector<PathEdge> source_edges;
  std::vector<PathEdge> target_edges;
  FrameId ancestor = kNoFrame;
  LookupFailure failure = walk(target, source, 0, source_edges, target_edges, &ancestor);
  if (!failure) stamp = commonNewest(frames_, source_edges, target_edges);
  return failure;
}

LookupFailure BufferCore::Impl::lookup(FrameId target, FrameId source, std::int64_t& stamp,
                                       Transform* value) const {
  if (target != source && quickLookup(target, source, stamp, value)) return {};
  return lookupByWalk(target, source, stamp, value);
}

LookupFailure BufferCore::Impl::lookupByWalk(FrameId target, FrameId source, std::int64_t& stamp,
                                             Transform* value) const {
  WalkScratch& s = scratch;
  LookupFailure failure;
  if (target == source) {
    if (stamp == 0) failure = latestCommonTime(target, source, stamp);
  } else {
    FrameId ancestor = kNoFrame;
    bool parent_changed = false;
    const bool check_only = value == nullptr && stamp != 0;
    failure = walk(target, source, stamp, s.source_edges, s.target_edges, &ancestor);
    if (!failure && check_only) {
      failure = sampleEdges(frames_, s.source_edges, stamp, nullptr, true);
      if (!failure) failure = sampleEdges(frames_, s.target_edges, stamp, nullptr, true);
    } else if (!failure && stamp == 0) {
      // The tree as of each edge's newest sample gives the latest common time; if an edge had
      // another parent at that time, walk the tree as it was then.
      stamp = commonNewest(frames_, s.source_edges, s.target_edges);
      if (!(failure = sampleEdges(frames_, s.source_edges, stamp, &parent_changed))) {
        failure = sampleEdges(frames_, s.target_edges, stamp, &parent_changed);
      }
      if (!failure && parent_changed && stamp != 0) {
        failure = walk(target, source, stamp, s.source_edges, s.target_edges, &ancestor);
        if (!failure) failure = sampleEdges(frames_, s.source_edges, stamp, nullptr);
        if (!failure) failure = sampleEdges(frames_, s.target_edges, stamp, nullptr);
      }
    } else if (!failure) {
      failure = sampleEdges(frames_, s.source_edges, stamp, nullptr);
      if (!failure) failure = sampleEdges(frames_, s.target_edges, stamp, nullptr);
    }
  }
  if (failure) {
    failure.target = target;
    failure.source = source;
    return failure;
  }
  if (value) {
    if (target == source) {
      *value = Transform::identity();
    } else {
      *value = pathValue(s);
    }
  }
  return {};
}

LookupFailure BufferCore::Impl::resolve(const std::string& name, const char* role,
                                        FrameId& id) const {
  const std::string_view stripped = stripLeadingSlash(name);
  if (!stripped.empty()) {
    id = idOf(stripped);
    if (id != kNoFrame) return {};
  }
  LookupFailure failure;
  failure.kind =
      stripped.empty() ? LookupFailure::Kind::kInvalidName : LookupFailure::Kind::kUnknownFrame;
  failure.frame = &name;
  failure.role = role;
  return failure;
}

// A failure is returned straight from resolve(), never assigned over another: copying the whole
// record a call has just written, field by field, stalls the processor on each copy.
LookupFailure BufferCore::Impl::resolvePair(const std::string& target, const std::string& source,
                                            FrameId& target_id, FrameId& source_id) const {
  if (const LookupFailure failure = resolve(target, "target", target_id)) return failure;
  return resolve(source, "source", source_id);
}

LookupFailure BufferCore::Impl::resolveAll(const std::string& target, const std::string& source,
                                           const std::string& fixed, FrameId& target_id,
                                           FrameId& source_id, FrameId& fixed_id) const {
  if (const LookupFailure failure = resolvePair(target, source, target_id, source_id)) {
    return failure;
  }
  return resolve(fixed, "fixed", fixed_id);
}

void BufferCore::Impl::updateStaticChains() {
  struct Chain {
    FrameId top;
    Transform top_T_frame;
  };
  std::vector<Chain> before;
  before.reserve(frames_.size());
  for (const FrameRecord& record : frames_) {
    before.push_back({record.static_top, record.static_top_T_frame});
  }
  computeStaticChains();
  // Edges into a frame whose chain changed hold samples anchored to the old chain.
  std::vector<char> changed(frames_.size(), 0);
  for (FrameId frame = 1; frame < frames_.size(); ++frame) {
    const FrameRecord& record = frames_[frame];
    const Chain& old = before[frame];
    changed[frame] =
        old.top != record.static_top ||
        old.top_T_frame.translation != record.static_top_T_frame.translation ||
        old.top_T_frame.rotation.coeffs() != record.static_top_T_frame.rotation.coeffs();
  }
  auto anchor = [this](FrameId parent) { return anchorOf(frames_, parent); };
  for (FrameRecord& record : frames_) {
    detail::TimeCache& cache = record.cache;
    if (cache.isStatic() || cache.empty()) continue;
    if (!cache.hasSingleParent() || changed[cache.newestParent()]) cache.reanchor(anchor);
  }
}

void BufferCore::Impl::computeStaticChains() {
  // Memoized climb: a frame's top is its static parent's top, found before the frame itself.
  constexpr FrameId kUnknown = static_cast<FrameId>(-1);
  for (FrameRecord& record : frames_) record.static_top = kUnknown;
  std::vector<FrameId> pending;
  for (FrameId start = 1; start < frames_.size(); ++start) {
    FrameId frame = start;
    while (frames_[frame].static_top == kUnknown && frames_[frame].cache.isStatic() &&
           pending.size() <= frames_.size()) {
      pending.push_back(frame);
      frame = frames_[frame].cache.staticValue().parent;
    }
    const bool looped = pending.size() > frames_.size();
    if (frames_[frame].static_top == kUnknown) {
      frames_[frame].static_top = frame;
      frames_[frame].static_top_T_frame = Transform::identity();
    }
    // A static loop would never end; frames on it step edge by edge, and lookups report it.
    for (auto it = pending.rbegin(); it != pending.rend(); ++it) {
      FrameRecord& record = frames_[*it];
      if (record.static_top != kUnknown) continue;
      const detail::EdgeValue& edge = record.cache.staticValue();
      const FrameRecord& parent = frames_[edge.parent];
      if (looped || parent.static_top == *it) {
        record.static_top = *it;
        record.static_top_T_frame = Transform::identity();
      } else {
        continueStaticChain(record, parent, edge.transform);
      }
    }
    pending.clear();
  }
  frames_[kNoFrame].static_top = kNoFrame;
}

}  // namespace lcmtf
