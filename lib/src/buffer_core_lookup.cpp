// Walking the frame tree: from both frames up to their common ancestor, then composing.
#include <algorithm>

#include "buffer_core_impl.hpp"

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
  std::vector<PathEdge> spare_source;
  std::vector<PathEdge> spare_target;
};
thread_local WalkScratch scratch;

// Walks up from `start` for more steps than there are frames to find the frames of the loop.
std::vector<FrameId> findLoop(const std::vector<FrameRecord>& frames, FrameId start,
                              std::int64_t stamp, bool latest) {
  std::vector<FrameId> visited;
  FrameId frame = start;
  while (frame != kNoFrame && visited.size() <= 2 * frames.size()) {
    const auto seen = std::find(visited.begin(), visited.end(), frame);
    if (seen != visited.end()) return std::vector<FrameId>(seen, visited.end());
    visited.push_back(frame);
    SampleStatus status;
    frame = latest ? (frames[frame].cache.empty() ? kNoFrame : frames[frame].cache.newest().parent)
                   : frames[frame].cache.parentAt(stamp, status);
  }
  return visited;
}

Transform composeUp(const std::vector<PathEdge>& edges) {
  Transform ancestor_T_frame;
  for (const PathEdge& edge : edges) ancestor_T_frame = edge.span.value() * ancestor_T_frame;
  return ancestor_T_frame;
}

}  // namespace

LookupFailure BufferCore::Impl::walk(FrameId target, FrameId source, std::int64_t stamp,
                                     std::vector<PathEdge>& source_edges,
                                     std::vector<PathEdge>& target_edges, FrameId* ancestor) const {
  const bool latest = stamp == 0;
  WalkScratch& s = scratch;
  if (s.visit_epoch.size() < frames_.size()) {
    s.visit_epoch.resize(frames_.size(), 0);
    s.visit_index.resize(frames_.size(), 0);
  }
  const std::uint64_t epoch = ++s.epoch;
  source_edges.clear();
  target_edges.clear();
  const std::size_t max_depth = frames_.size();

  auto step = [&](FrameId frame, PathEdge& edge) {
    const detail::TimeCache& cache = frames_[frame].cache;
    edge.child = frame;
    if (latest) {
      edge.status = cache.empty() ? SampleStatus::kEmpty : SampleStatus::kOk;
      edge.parent = cache.empty() ? kNoFrame : cache.newest().parent;
    } else {
      edge.parent = cache.parentAt(stamp, edge.status);
    }
  };
  auto loopFailure = [&](FrameId from) {
    LookupFailure failure;
    failure.kind = LookupFailure::Kind::kLoop;
    failure.target = target;
    failure.source = source;
    failure.requested = stamp;
    failure.loop = findLoop(frames_, from, stamp, latest);
    return failure;
  };

  FrameId frame = source;
  FrameId source_root = source;
  for (std::size_t depth = 0;; ++depth) {
    if (depth > max_depth) return loopFailure(source);
    s.visit_epoch[frame] = epoch;
    s.visit_index[frame] = static_cast<std::uint32_t>(source_edges.size());
    if (frame == target) {
      *ancestor = target;
      return {};
    }
    PathEdge edge;
    step(frame, edge);
    if (edge.parent == kNoFrame) {
      source_root = frame;
      break;
    }
    source_edges.push_back(edge);
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
    PathEdge edge;
    step(frame, edge);
    if (edge.parent == kNoFrame) {
      LookupFailure failure;
      failure.kind = LookupFailure::Kind::kNotConnected;
      failure.target = target;
      failure.source = source;
      failure.requested = stamp;
      failure.edge_child = source_root;  // the two roots
      failure.edge_parent = frame;
      return failure;
    }
    target_edges.push_back(edge);
    frame = edge.parent;
  }
}

namespace {

// The first edge of the path without data at `stamp`, as a failure; fills the spans otherwise.
LookupFailure sampleEdges(const std::vector<FrameRecord>& frames, std::vector<PathEdge>& edges,
                          std::int64_t stamp) {
  for (PathEdge& edge : edges) {
    const detail::TimeCache& cache = frames[edge.child].cache;
    if (edge.status == SampleStatus::kOk) {
      cache.find(stamp, edge.span);
      continue;
    }
    LookupFailure failure;
    failure.kind = edge.status == SampleStatus::kPast ? LookupFailure::Kind::kPast
                                                      : LookupFailure::Kind::kFuture;
    failure.edge_child = edge.child;
    failure.edge_parent = edge.parent;
    failure.requested = stamp;
    failure.oldest = cache.oldest().stamp;
    failure.newest = cache.newest().stamp;
    return failure;
  }
  return {};
}

}  // namespace

LookupFailure BufferCore::Impl::latestCommonTime(FrameId target, FrameId source,
                                                 std::int64_t& stamp) const {
  stamp = 0;
  if (target == source) {
    const detail::TimeCache& cache = frames_[target].cache;
    if (!cache.empty() && !cache.isStatic()) stamp = cache.newest().stamp;
    return {};
  }
  FrameId ancestor = kNoFrame;
  LookupFailure failure =
      walk(target, source, 0, scratch.spare_source, scratch.spare_target, &ancestor);
  if (failure) return failure;
  bool any_dynamic = false;
  std::int64_t common = 0;
  for (const auto* edges : {&scratch.spare_source, &scratch.spare_target}) {
    for (const PathEdge& edge : *edges) {
      const detail::TimeCache& cache = frames_[edge.child].cache;
      if (cache.isStatic()) continue;
      common = any_dynamic ? std::min(common, cache.newest().stamp) : cache.newest().stamp;
      any_dynamic = true;
    }
  }
  stamp = common;
  return {};
}

LookupFailure BufferCore::Impl::lookup(FrameId target, FrameId source, std::int64_t stamp,
                                       TransformStamped* out) const {
  if (stamp == 0) {
    LookupFailure failure = latestCommonTime(target, source, stamp);
    if (failure) return failure;
  }
  if (target == source) {
    if (out)
      *out = TransformStamped{fromUtime(stamp), std::string(nameOf(target)),
                              std::string(nameOf(source)), Transform::identity()};
    return {};
  }
  WalkScratch& s = scratch;
  FrameId ancestor = kNoFrame;
  LookupFailure failure = walk(target, source, stamp, s.source_edges, s.target_edges, &ancestor);
  if (!failure) failure = sampleEdges(frames_, s.source_edges, stamp);
  if (!failure) failure = sampleEdges(frames_, s.target_edges, stamp);
  if (failure) {
    failure.target = target;
    failure.source = source;
    return failure;
  }
  if (out) {
    const Transform ancestor_T_source = composeUp(s.source_edges);
    out->stamp = fromUtime(stamp);
    out->parent_frame.assign(nameOf(target));
    out->child_frame.assign(nameOf(source));
    out->transform = s.target_edges.empty()
                         ? ancestor_T_source
                         : composeUp(s.target_edges).inverse() * ancestor_T_source;
  }
  return {};
}

LookupFailure BufferCore::Impl::resolve(const std::string& name, const char* role,
                                        FrameId& id) const {
  const std::string_view stripped = stripLeadingSlash(name);
  LookupFailure failure;
  failure.frame = name;
  failure.role = role;
  if (stripped.empty()) {
    failure.kind = LookupFailure::Kind::kInvalidName;
    return failure;
  }
  id = idOf(stripped);
  if (id == kNoFrame) {
    failure.kind = LookupFailure::Kind::kUnknownFrame;
    failure.frame = std::string(stripped);
    return failure;
  }
  return {};
}

LookupFailure BufferCore::Impl::resolveAll(const std::string& target, const std::string& source,
                                           const std::string& fixed) const {
  FrameId id = kNoFrame;
  LookupFailure failure = resolve(target, "target", id);
  if (!failure) failure = resolve(source, "source", id);
  if (!failure) failure = resolve(fixed, "fixed", id);
  return failure;
}

}  // namespace lcmtf
