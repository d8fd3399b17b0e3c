// Lookups by the root paths: the two frames' paths are compared to find where they meet, and
// the steps below that are sampled, interpolated and composed in batches. Anything unusual
// (a frame without a path, an edge whose parent changed within its history, data missing)
// is left to the walk.
#include <algorithm>
#include <limits>
#include <new>

#include "buffer_core_impl.hpp"
#include "compose.hpp"
#include "lookup_mode.hpp"
#include "path_plan.hpp"
#include "quick_path.hpp"

namespace lcmtf {

namespace {

using detail::kMostQuickSteps;
using detail::PathPlan;
using detail::PlanStep;
using detail::QuickPath;
using detail::QuickPlan;

// Where two paths meet: how many steps of each are taken, and whether each one's last step
// is anchored. Where each path's last step crosses the static chain the other path crosses
// as well (or is), the edges' own values are used and the chain left out: a lookup of a
// dynamic edge's child in its parent then gives the stored samples themselves, not with the
// chain applied and taken off again.
struct MeetingPoint {
  std::size_t source_count;
  std::size_t target_count;
  bool source_anchored;
  bool target_anchored;
};

MeetingPoint meetingPoint(const RootPaths::Path& up_from_source,
                          const RootPaths::Path& up_from_target, FrameId source, FrameId target) {
  std::size_t source_count = up_from_source.size;
  std::size_t target_count = up_from_target.size;
  // Above the first frame both paths reach, they are the same and cancel out.
  while (source_count > 0 && target_count > 0 &&
         up_from_source.steps[source_count - 1].child ==
             up_from_target.steps[target_count - 1].child) {
    --source_count;
    --target_count;
  }
  MeetingPoint meeting{source_count, target_count,
                       source_count > 0 && up_from_source.steps[source_count - 1].anchored(),
                       target_count > 0 && up_from_target.steps[target_count - 1].anchored()};
  if (source_count == 0 || target_count == 0) return meeting;
  const RootStep& last_source = up_from_source.steps[source_count - 1];
  const RootStep& last_target = up_from_target.steps[target_count - 1];
  if (last_source.anchored() && last_target.anchored() &&
      last_source.parent == last_target.parent) {
    meeting.source_anchored = meeting.target_anchored = false;
  } else if (last_source.anchored() && last_source.parent == target) {
    meeting.source_anchored = false;
    meeting.target_count = 0;
  } else if (last_target.anchored() && last_target.parent == source) {
    meeting.target_anchored = false;
    meeting.source_count = 0;
  }
  return meeting;
}

// The paths up from both frames and where they meet; false when the root paths cannot answer:
// a frame has none, the frames are on different trees, or the steps are more than a quick
// plan holds.
[[gnu::always_inline]] inline bool findMeeting(const RootPaths& root_paths,
                                               const FrameTable& frames, FrameId target,
                                               FrameId source, RootPaths::Path& up_from_source,
                                               RootPaths::Path& up_from_target,
                                               MeetingPoint& meeting) {
  if (!root_paths.find(frames, source, up_from_source) ||
      !root_paths.find(frames, target, up_from_target) ||
      up_from_source.root != up_from_target.root) {
    return false;
  }
  meeting = meetingPoint(up_from_source, up_from_target, source, target);
  return meeting.source_count + meeting.target_count <= kMostQuickSteps;
}

// What planning a lookup at the latest common time learns of the dynamic steps as it takes
// them, so that it needs no second pass over them once it knows that time.
struct LatestBounds {
  CommonNewest common;
  std::int64_t single_parent_from = std::numeric_limits<std::int64_t>::min();
  bool zero_stamped = false;  // an edge whose newest sample is stamped 0

  void add(const detail::TimeCache& cache) {
    common.add(cache.newestStamp());
    single_parent_from = std::max(single_parent_from, cache.singleParentFrom());
    zero_stamped = zero_stamped || cache.newestStamp() == 0;
  }
  // Whether every edge added has data at `at`, all of it under one parent. An edge whose newest
  // sample is stamped 0 sets no bound on the common time, and may lack data there.
  bool cover(std::int64_t at) const {
    return at >= single_parent_from && !(zero_stamped && at > 0);
  }
  // The latest common time of the edges added, into `at` (left as it is when none is dynamic);
  // false when they do not all cover it.
  bool commonTime(std::int64_t& at) const {
    if (!common.any_dynamic) return true;
    at = common.stamp;
    return cover(at);
  }
};

// Fills `out` with the steps of one side; false when a dynamic edge among them has changed
// parent within its history (the tree at `stamp` may not be the paths'), or has no data at
// `stamp` (0: both checked later, through `latest`, and the samples near each edge's newest
// hinted at: they are seldom long out of the cache, and loading them ahead cost more than it
// saved).
// The paths were built with each edge's newest parent. Inlined into planPath(), which calls
// it for each side: the calls took 3 % of a lookup on the wide tree of buffer_core_bench.
// Built apart for lookups at the latest common time, so that neither loop asks at every step
// which kind of lookup it plans; with the second pass over the steps this saves, 2 % of the
// latest-time lookups on pr2 and wide, 1-2 % of the others.
template <bool kAtLatest>
[[gnu::always_inline]] inline bool takeSteps(const RootStep* steps, std::size_t count,
                                             bool last_anchored, std::int64_t stamp, bool prefetch,
                                             PlanStep* out, LatestBounds& latest) {
  for (std::size_t i = 0; i < count; ++i) {
    const RootStep& step = steps[i];
    PlanStep& quick = out[i];
    quick = PlanStep{step.cache, step.fixed, step.anchor, true, detail::TimeCache::kNoHint};
    if (!step.cache) continue;
    const detail::TimeCache& cache = *step.cache;
    if constexpr (kAtLatest) {
      latest.add(cache);
      quick.hint = cache.hintNearNewest();
    } else {
      if (!cache.spansUnderOneParent(stamp)) return false;
      if (prefetch) quick.hint = cache.prefetch(stamp);
    }
  }
  if (count > 0 && !last_anchored) out[count - 1].anchor = nullptr;
  return true;
}

// takeSteps() for both sides of where the paths meet.
template <bool kAtLatest>
[[gnu::always_inline]] inline bool takeBothSides(const RootPaths::Path& up_from_source,
                                                 const RootPaths::Path& up_from_target,
                                                 const MeetingPoint& meeting, std::int64_t stamp,
                                                 bool prefetch, PlanStep* out,
                                                 LatestBounds& latest) {
  return takeSteps<kAtLatest>(up_from_source.steps, meeting.source_count, meeting.source_anchored,
                              stamp, prefetch, out, latest) &&
         takeSteps<kAtLatest>(up_from_target.steps, meeting.target_count, meeting.target_anchored,
                              stamp, prefetch, out + meeting.source_count, latest);
}

// Whether the tree at `at` may differ from the root paths' above where two paths meet: a
// dynamic edge there that has changed parent within its history and has data at `at` may then
// have another parent, which may close a loop or lead elsewhere, and a lookup climbs past the
// meeting point to the root (as tf's does) unless it reaches the target first.
bool mayDifferAbove(const RootPaths::Path& path, std::size_t from, std::int64_t at) {
  for (std::size_t i = from; i < path.size; ++i) {
    const detail::TimeCache* cache = path.steps[i].cache;
    if (cache && !cache->hasSingleParent() && cache->oldestStamp() <= at &&
        at <= cache->newestStamp()) {
      return true;
    }
  }
  return false;
}

// Whether a lookup at `at` from `up_from_source` may climb past where the paths meet onto
// another tree than theirs (mayDifferAbove()), when any edge has changed parent. Where the
// target is on the source's way up, the climb ends there; else it goes on.
bool mayClimbElsewhere(const RootPaths::Path& up_from_source, const MeetingPoint& meeting,
                       std::int64_t at, bool parent_changes) {
  return parent_changes && meeting.target_count > 0 &&
         mayDifferAbove(up_from_source, meeting.source_count, at);
}

// The steps of one side of a lookup at the latest common time, taken with their samples: a
// static step's value, and for a dynamic edge an interpolation task between its two newest
// samples, whose ratio waits for that time. False when an edge has fewer than two samples.
[[gnu::always_inline]] inline bool sampleNewestPairs(const RootStep* steps, std::size_t count,
                                                     bool last_anchored, std::size_t first,
                                                     QuickPath& path, LatestBounds& latest) {
  for (std::size_t i = 0; i < count; ++i) {
    const RootStep& step = steps[i];
    if (!step.cache) {
      path.values[first + i] = step.fixed;
      continue;
    }
    const detail::TimeCache& cache = *step.cache;
    latest.add(cache);
    const std::size_t index = path.task_count++;
    detail::InterpolationTask& task = path.tasks[index];
    if (!cache.newestPair(task.older, task.newer, task.arc_squared)) return false;
    task.out = ::new (static_cast<void*>(path.rooms[index].bytes)) Transform;
    task.anchor = i + 1 == count && !last_anchored ? nullptr : step.anchor;
    path.task_caches[index] = &cache;
    path.values[first + i] = task.out;
  }
  return true;
}

// Plans a lookup at the latest common time and takes its samples in the same pass over the
// steps, where the usual plan leaves them to a second pass once it knows that time: each edge
// is taken between its two newest samples, and each ratio worked out once the time is known.
// False when an edge's two newest samples do not span that time (another edge's newest is
// older than both), or the plan cannot be made (as planPath()). Against the usual plan,
// fastest of three alternating rounds of buffer_core_bench: the latest-time lookups of pr2
// 170 -> 164 ns and of deep_chain 99.5 -> 95.9; wide's lookups 2-3 % slower (wide's latest
// ones included), pr2's and deep_chain's others within 2 %.
bool sampleLatest(const RootPaths::Path& up_from_source, const RootPaths::Path& up_from_target,
                  const MeetingPoint& meeting, bool parent_changes, QuickPath& path) {
  LatestBounds latest;
  path.task_count = 0;
  if (!sampleNewestPairs(up_from_source.steps, meeting.source_count, meeting.source_anchored, 0,
                         path, latest) ||
      !sampleNewestPairs(up_from_target.steps, meeting.target_count, meeting.target_anchored,
                         meeting.source_count, path, latest)) {
    return false;
  }
  std::int64_t at = 0;
  if (!latest.commonTime(at)) return false;
  for (std::size_t index = 0; index < path.task_count; ++index) {
    if (!path.task_caches[index]->ratioInNewestPair(at, path.tasks[index].ratio)) return false;
  }
  if (mayClimbElsewhere(up_from_source, meeting, at, parent_changes)) return false;
  path.plan = PathPlan{nullptr, meeting.source_count, meeting.target_count, at};
  path.sampled = true;
  return true;
}

// The first of sampleAt()'s two passes over a longer path's steps, for one side: false when a
// dynamic edge has changed parent within its history or has no data at `stamp` (as
// takeSteps()), else where each dynamic edge's samples likely are into `hints`, their loads
// started.
[[gnu::always_inline]] inline bool hintSide(const RootStep* steps, std::size_t count,
                                            std::int64_t stamp, std::size_t* hints) {
  for (std::size_t i = 0; i < count; ++i) {
    const detail::TimeCache* cache = steps[i].cache;
    if (!cache) continue;
    if (!cache->spansUnderOneParent(stamp)) return false;
    hints[i] = cache->prefetch(stamp);
  }
  return true;
}

// The value of each of one side's steps into `values`, the interpolations they need into
// `sampler`: where hintSide() has checked the steps (kHinted), from its `hints`; else checking
// each step as hintSide() does, false when one fails.
template <bool kHinted>
[[gnu::always_inline]] inline bool sampleSide(const RootStep* steps, std::size_t count,
                                              bool last_anchored, std::int64_t stamp,
                                              const std::size_t* hints,
                                              detail::PathSampler& sampler,
                                              const Transform** values) {
  for (std::size_t i = 0; i < count; ++i) {
    const RootStep& step = steps[i];
    if (!step.cache) {
      values[i] = step.fixed;
      continue;
    }
    const detail::TimeCache& cache = *step.cache;
    std::size_t hint;
    if constexpr (kHinted) {
      hint = hints[i];
    } else {
      if (!cache.spansUnderOneParent(stamp)) return false;
      hint = cache.hintAt(stamp);
    }
    const Transform* anchor = i + 1 == count && !last_anchored ? nullptr : step.anchor;
    values[i] = sampler.take(cache.spanWithin(stamp, hint), anchor);
  }
  return true;
}

// Paths of up to this many steps are sampled in one pass.
constexpr std::size_t kMostStepsInOnePass = 4;

// Plans a lookup at `stamp` (not 0) and takes its samples straight from the root paths' steps.
// A path of a few steps takes them in one pass, each edge as its check passes: against a plan
// of the steps and a second pass over it, 10 % fewer instructions on the deepest lookups of
// buffer_core_bench's wide tree. A longer path takes them in two: the first checks every edge
// and starts the loads of its samples, so that they come from memory together, where those of
// an edge taken with its check would wait for the processor to finish with the edges before
// (on the forest of buffer_core_bench, one pass made the random lookups 11-16 % slower).
[[gnu::always_inline]] inline bool sampleAt(const RootPaths::Path& up_from_source,
                                            const RootPaths::Path& up_from_target,
                                            const MeetingPoint& meeting, std::int64_t stamp,
                                            bool parent_changes, QuickPath& path) {
  if (mayClimbElsewhere(up_from_source, meeting, stamp, parent_changes)) return false;
  detail::PathSampler sampler({path.tasks, path.rooms});
  const Transform** const target_values = path.values + meeting.source_count;
  if (meeting.source_count + meeting.target_count <= kMostStepsInOnePass) {
    if (!sampleSide<false>(up_from_source.steps, meeting.source_count, meeting.source_anchored,
                           stamp, nullptr, sampler, path.values) ||
        !sampleSide<false>(up_from_target.steps, meeting.target_count, meeting.target_anchored,
                           stamp, nullptr, sampler, target_values)) {
      return false;
    }
  } else {
    std::size_t* const target_hints = path.hints + meeting.source_count;
    if (!hintSide(up_from_source.steps, meeting.source_count, stamp, path.hints) ||
        !hintSide(up_from_target.steps, meeting.target_count, stamp, target_hints)) {
      return false;
    }
    sampleSide<true>(up_from_source.steps, meeting.source_count, meeting.source_anchored, stamp,
                     path.hints, sampler, path.values);
    sampleSide<true>(up_from_target.steps, meeting.target_count, meeting.target_anchored, stamp,
                     target_hints, sampler, target_values);
  }
  path.task_count = sampler.taskCount();
  path.plan = PathPlan{nullptr, meeting.source_count, meeting.target_count, stamp};
  path.sampled = true;
  return true;
}

// Plans the lookup of `source` in `target` at `stamp` (0: the latest common time, which the
// plan's `at` then gives) into `path`, starting the loads of the samples when `prefetch`, and at
// the latest common time taking them too into `sampling` (sampleLatest()), the QuickPath that
// `path` is, unless null; false when the root paths cannot answer. `parent_changes` says whether
// any edge's history holds more than one parent.
bool planPath(const RootPaths& root_paths, const FrameTable& frames, FrameId target, FrameId source,
              std::int64_t stamp, bool prefetch, bool parent_changes, QuickPlan& path,
              QuickPath* sampling) {
  RootPaths::Path up_from_source;
  RootPaths::Path up_from_target;
  MeetingPoint meeting;
  if (!findMeeting(root_paths, frames, target, source, up_from_source, up_from_target, meeting)) {
    return false;
  }
  if (stamp == 0 && sampling &&
      sampleLatest(up_from_source, up_from_target, meeting, parent_changes, *sampling)) {
    return true;
  }
  PlanStep* const steps = path.steps;
  LatestBounds latest;
  if (!(stamp == 0 ? takeBothSides<true>(up_from_source, up_from_target, meeting, stamp, prefetch,
                                         steps, latest)
                   : takeBothSides<false>(up_from_source, up_from_target, meeting, stamp, prefetch,
                                          steps, latest))) {
    return false;
  }
  std::int64_t at = stamp;
  if (stamp == 0 && !latest.commonTime(at)) return false;
  if (mayClimbElsewhere(up_from_source, meeting, at, parent_changes)) return false;
  path.plan = PathPlan{steps, meeting.source_count, meeting.target_count, at};
  return true;
}

// The sum of the translations of a plan's step values, the scale of its rounding errors.
double magnitudeOf(const PathPlan& plan, const Transform* const* values) {
  double sum = 0.0;
  for (std::size_t i = 0; i < plan.size(); ++i) sum += values[i]->translation.norm();
  return sum;
}

// The static chain that the two halves of a time-travel lookup whose fixed frame is above both
// frames cross, one each way, as their last steps, dropped from both plans; null when there is
// none. Where each half's last step is a dynamic edge anchored to the static chain above one
// same parent (as a robot's frames hang below map -> odom -> base_link), the chain and its
// inverse cancel in the product. Two compositions fewer: 4 % of the instructions of a
// time-travel lookup on the wide tree of buffer_core_bench, 2 % on deep_chain.
const Transform* dropSharedAnchor(QuickPlan& source_path, QuickPlan& target_path) {
  const std::size_t source_count = source_path.plan.source_count;
  const std::size_t target_count = target_path.plan.target_count;
  if (source_count == 0 || target_count == 0) return nullptr;
  PlanStep& source_last = source_path.steps[source_count - 1];
  PlanStep& target_last = target_path.steps[target_count - 1];
  const Transform* const anchor = source_last.anchor;
  if (!anchor || anchor != target_last.anchor) return nullptr;
  source_last.anchor = target_last.anchor = nullptr;
  return anchor;
}

// Interpolation tasks and rooms for the steps of `Paths` quick paths.
template <std::size_t Paths>
struct QuickSamplerRoom {
  detail::InterpolationTask tasks[Paths * kMostQuickSteps];
  detail::TransformRoom rooms[Paths * kMostQuickSteps];
  detail::SamplerStorage storage() { return {tasks, rooms}; }
};

}  // namespace

bool BufferCore::Impl::planQuickLookup(FrameId target, FrameId source, std::int64_t stamp,
                                       QuickPath& path) const {
  if (stamp == 0) return planQuickly(target, source, stamp, true, path, &path);
  RootPaths::Path up_from_source;
  RootPaths::Path up_from_target;
  MeetingPoint meeting;
  return quickLookupsApply() &&
         findMeeting(root_paths_, frames_, target, source, up_from_source, up_from_target,
                     meeting) &&
         sampleAt(up_from_source, up_from_target, meeting, stamp, parent_changing_edges_ != 0,
                  path);
}

bool BufferCore::Impl::planQuickly(FrameId target, FrameId source, std::int64_t stamp,
                                   bool prefetch, QuickPlan& path, QuickPath* sampling) const {
  return quickLookupsApply() && planPath(root_paths_, frames_, target, source, stamp, prefetch,
                                         parent_changing_edges_ != 0, path, sampling);
}

Transform BufferCore::Impl::quickValue(FrameId target, FrameId source, std::int64_t stamp,
                                       QuickPath& path) const {
  if (path.sampled) {
    detail::interpolateBatch(path.tasks, path.task_count);
  } else {
    detail::PathSampler sampler({path.tasks, path.rooms});
    sampler.sample(path.plan, path.values);
    sampler.run();
  }
  Transform value;
  detail::productOf(path.plan, path.values, value);
  if (detail::crossCheckQuickLookups()) {
    crossCheck(target, source, stamp, path.plan.at, &value, magnitudeOf(path.plan, path.values));
  }
  return value;
}

bool BufferCore::Impl::quickLookupInto(FrameId target, FrameId source, std::int64_t& stamp,
                                       Transform& value) const {
  QuickPath path;
  if (!planQuickLookup(target, source, stamp, path)) return false;
  value = quickValue(target, source, stamp, path);
  stamp = path.plan.at;
  return true;
}

bool BufferCore::Impl::quickLookup(FrameId target, FrameId source, std::int64_t& stamp,
                                   Transform* value) const {
  if (value) return quickLookupInto(target, source, stamp, *value);
  // Whether it can answer, and at what time: the plan alone, without the rooms for sampling it.
  QuickPlan path;
  if (!planQuickly(target, source, stamp, false, path, nullptr)) return false;
  if (detail::crossCheckQuickLookups()) {
    crossCheck(target, source, stamp, path.plan.at, nullptr, 0.0);
  }
  stamp = path.plan.at;
  return true;
}

bool BufferCore::Impl::quickTimeTravel(FrameId target, std::int64_t& target_stamp, FrameId source,
                                       std::int64_t& source_stamp, FrameId fixed,
                                       Transform& value) const {
  if (source == fixed || target == fixed) return false;
  QuickPlan source_path;
  QuickPlan target_path;
  // Each half's steps are sampled with the other's, in one batch: neither samples as it plans.
  if (!planQuickly(fixed, source, source_stamp, true, source_path, nullptr) ||
      !planQuickly(target, fixed, target_stamp, true, target_path, nullptr)) {
    return false;
  }
  // Where the fixed frame is where each path meets (an ancestor of both frames, as a map or
  // odom frame usually is), target_T_source is one product over the steps of both, with no
  // composition of two halves after it: 5 % of a time-travel lookup on the wide tree of
  // buffer_core_bench.
  const bool fixed_above_both =
      source_path.plan.target_count == 0 && target_path.plan.source_count == 0;
  const Transform* const dropped_anchor =
      fixed_above_both ? dropSharedAnchor(source_path, target_path) : nullptr;
  QuickSamplerRoom<2> room;
  detail::PathSampler sampler(room.storage());
  const Transform* source_values[kMostQuickSteps];
  const Transform* target_values[kMostQuickSteps];
  sampler.sample(source_path.plan, source_values);
  sampler.sample(target_path.plan, target_values);
  sampler.run();
  if (fixed_above_both) {
    detail::pathProduct(source_values, source_path.plan.source_count, target_values,
                        target_path.plan.target_count, value);
  }
  const bool cross_check = detail::crossCheckQuickLookups();
  if (!fixed_above_both || cross_check) {
    Transform fixed_T_source;
    Transform target_T_fixed;
    detail::productOf(source_path.plan, source_values, fixed_T_source);
    detail::productOf(target_path.plan, target_values, target_T_fixed);
    if (cross_check) {
      double anchor_magnitude = 0.0;
      if (dropped_anchor) {
        fixed_T_source = detail::composed(*dropped_anchor, fixed_T_source);
        target_T_fixed = detail::composed(target_T_fixed, dropped_anchor->inverse());
        anchor_magnitude = dropped_anchor->translation.norm();
      }
      crossCheck(fixed, source, source_stamp, source_path.plan.at, &fixed_T_source,
                 magnitudeOf(source_path.plan, source_values) + anchor_magnitude);
      crossCheck(target, fixed, target_stamp, target_path.plan.at, &target_T_fixed,
                 magnitudeOf(target_path.plan, target_values) + anchor_magnitude);
    }
    if (!fixed_above_both) value = detail::composed(target_T_fixed, fixed_T_source);
  }
  source_stamp = source_path.plan.at;
  target_stamp = target_path.plan.at;
  return true;
}

}  // namespace lcmtf
