// Walking the frame tree: from both frames up to their common ancestor, then composing.
#include <algorithm>

#include <cstdio>
#include <cstdlib>

#include "buffer_core_impl.hpp"
#include "path_plan.hpp"

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
  std::vector<detail::PlanStep> steps;
  std::vector<detail::InterpolationTask> tasks;
  std::vector<detail::TransformRoom> rooms;
  std::vector<const Transform*> values;
};
thread_local WalkScratch scratch;

}  // namespace

// Walks up from `start` for more steps than there are frames to find the frames of the loop.
std::vector<FrameId> findLoop(const FrameTable& frames, FrameId start, std::int64_t stamp,
                              bool latest) {
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
void stepUp(const FrameTable& frames, FrameId frame, std::int64_t stamp, PathEdge& edge) {
  const detail::TimeCache& cache = frames[frame].cache;
  edge.child = frame;
  edge.status = SampleStatus::kOk;
  if (cache.isStatic()) {
    edge.fixed = &cache.staticTransform();
    edge.parent = cache.staticParent();
  } else {
    edge.fixed = nullptr;
    edge.parent = stamp == 0 ? cache.newestParent() : cache.parentAt(stamp, edge.status);
  }
}

// The value of the path the walk found at `stamp`, by the same sampler and product as the
// quick lookups.
Transform pathValue(const FrameTable& frames, WalkScratch& s, std::int64_t stamp) {
  const std::size_t count = s.source_edges.size() + s.target_edges.size();
  s.steps.clear();
  for (const auto* edges : {&s.source_edges, &s.target_edges}) {
    for (const PathEdge& edge : *edges) {
      const detail::TimeCache* cache = edge.isDynamic() ? &frames[edge.child].cache : nullptr;
      s.steps.push_back({cache, edge.fixed, nullptr, false, detail::TimeCache::kNoHint});
    }
  }
  if (s.tasks.size() < count) {
    s.tasks.resize(count);
    s.rooms.resize(count);
    s.values.resize(count);
  }
  const detail::PathPlan plan{s.steps.data(), s.source_edges.size(), s.target_edges.size(), stamp};
  detail::PathSampler sampler({s.tasks.data(), s.rooms.data()});
  sampler.sample(plan, s.values.data());
  sampler.run();
  Transform target_T_source;
  detail::productOf(plan, s.values.data(), target_T_source);
  return target_T_source;
}

// A dynamic edge without data at `stamp`, as a failure.
LookupFailure missingData(const FrameTable& frames, const PathEdge& edge, std::int64_t stamp) {
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

// The newest stamp every dynamic edge of the walk has data at; 0 when all are static.
std::int64_t commonNewest(const FrameTable& frames, const std::vector<PathEdge>& source_edges,
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
  return latestCommonTimeByWalk(target, source, stamp);
}

LookupFailure BufferCore::Impl::latestCommonTimeByWalk(FrameId target, FrameId source,
                                                       std::int64_t& stamp) const {
  WalkScratch& s = scratch;
  FrameId ancestor = kNoFrame;
  const LookupFailure failure = walk(target, source, 0, s.source_edges, s.target_edges, &ancestor);
  stamp = failure ? 0 : commonNewest(frames_, s.source_edges, s.target_edges);
  return failure;
}

LookupFailure BufferCore::Impl::findGap(const std::vector<PathEdge>& edges,
                                        std::int64_t stamp) const {
  for (const PathEdge& edge : edges) {
    if (!edge.isDynamic()) continue;
    LookupFailure failure;
    if (frames_[edge.child].cache.samplesAround(stamp, failure.oldest, failure.newest) &&
        detail::saturatingSubtract(failure.newest, failure.oldest) > max_gap_) {
      failure.kind = LookupFailure::Kind::kGap;
      failure.edge_child = edge.child;
      failure.edge_parent = edge.parent;
      failure.requested = stamp;
      return failure;
    }
  }
  return {};
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
    // As tf does: the latest common time is found in the tree as of each edge's newest sample,
    // and the lookup then made in the tree as it was at that time.
    // When that time is none (only static edges on the way), the walk that found it has the
    // path already.
    const bool latest = stamp == 0;
    if (latest) failure = latestCommonTimeByWalk(target, source, stamp);
    FrameId ancestor = kNoFrame;
    if (!failure && !(latest && stamp == 0)) {
      failure = walk(target, source, stamp, s.source_edges, s.target_edges, &ancestor);
      if (!failure && max_gap_ != 0) failure = findGap(s.source_edges, stamp);
      if (!failure && max_gap_ != 0) failure = findGap(s.target_edges, stamp);
    }
  }
  if (failure) {
    failure.target = target;
    failure.source = source;
    return failure;
  }
  if (value) *value = target == source ? Transform::identity() : pathValue(frames_, s, stamp);
  return {};
}

namespace {

// The same value but for rounding: the translations to within a part in 1e9 of `magnitude`
// (composing through a chain of large translations rounds at their scale), or both overflowed
// (finite translations near the largest double compose to infinities), and the rotations to
// within the angle whose cosine is 1 - 1e-12, exactly unit or not.
bool sameValue(const Transform& a, const Transform& b, double magnitude) {
  const double cosine =
      std::abs(a.rotation.dot(b.rotation)) / (a.rotation.norm() * b.rotation.norm());
  const bool finite = a.translation.allFinite() && b.translation.allFinite();
  const bool overflowed = !a.translation.allFinite() && !b.translation.allFinite();
  return (overflowed ||
          (finite && (a.translation - b.translation).norm() <= 1e-9 * (1.0 + magnitude))) &&
         cosine >= 1.0 - 1e-12;
}

std::string valueText(const Transform& value) {
  char text[200];
  std::snprintf(text, sizeof text, "t [%.17g %.17g %.17g] q [%.17g %.17g %.17g %.17g]",
                value.translation.x(), value.translation.y(), value.translation.z(),
                value.rotation.x(), value.rotation.y(), value.rotation.z(), value.rotation.w());
  return text;
}

}  // namespace

void BufferCore::Impl::crossCheck(FrameId target, FrameId source, std::int64_t requested,
                                  std::int64_t answered, const Transform* quick,
                                  double magnitude) const {
  std::int64_t stamp = requested;
  Transform walked;
  const LookupFailure failure = lookupByWalk(target, source, stamp, quick ? &walked : nullptr);
  if (!failure && stamp == answered && (!quick || sameValue(*quick, walked, magnitude))) return;
  const std::string walk_answer =
      failure ? describe(failure, "the walk")
              : "at " + std::to_string(stamp) + (quick ? ": " + valueText(walked) : std::string());
  std::fprintf(stderr,
               "lcmtf: a quick lookup and the walk disagree on %s in %s at %lld:\n"
               "  quick: at %lld%s%s\n  walk:  %s\n",
               quoted(source).c_str(), quoted(target).c_str(), static_cast<long long>(requested),
               static_cast<long long>(answered), quick ? ": " : "",
               quick ? valueText(*quick).c_str() : "", walk_answer.c_str());
  std::abort();
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
      frame = frames_[frame].cache.staticParent();
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
      const FrameRecord& parent = frames_[record.cache.staticParent()];
      if (looped || parent.static_top == *it) {
        record.static_top = *it;
        record.static_top_T_frame = Transform::identity();
      } else {
        continueStaticChain(record, parent, record.cache.staticTransform());
      }
    }
    pending.clear();
  }
  frames_[kNoFrame].static_top = kNoFrame;
}

}  // namespace lcmtf
