// Lookups by the root paths: the two frames' paths are compared to find where they meet, and
// the steps below that are sampled, interpolated and composed in batches. Anything unusual
// (a frame without a path, an edge whose parent changed within its history, data missing)
// is left to the walk.
#include <algorithm>
#include <new>

#include "batch_interpolation.hpp"
#include "buffer_core_impl.hpp"
#include "compose.hpp"
#include "path_product.hpp"

namespace lcmtf {

namespace {

// Longer paths are left to the walk, so that a quick lookup needs no heap.
constexpr std::size_t kMostSteps = 64;

// A step to take: a static value, or the history of a dynamic edge. Left uninitialized in
// arrays sized for the longest path; takeSteps() sets every field.
struct QuickStep {
  const detail::TimeCache* cache;
  const Transform* fixed;
  bool anchored;
  std::size_t hint;
};

// Room for a transform, constructed only when used.
struct TransformRoom {
  alignas(Transform) unsigned char bytes[sizeof(Transform)];
};

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
                       source_count > 0 && up_from_source.steps[source_count - 1].anchored,
                       target_count > 0 && up_from_target.steps[target_count - 1].anchored};
  if (source_count == 0 || target_count == 0) return meeting;
  const RootStep& last_source = up_from_source.steps[source_count - 1];
  const RootStep& last_target = up_from_target.steps[target_count - 1];
  if (last_source.anchored && last_target.anchored && last_source.parent == last_target.parent) {
    meeting.source_anchored = meeting.target_anchored = false;
  } else if (last_source.anchored && last_source.parent == target) {
    meeting.source_anchored = false;
    meeting.target_count = 0;
  } else if (last_target.anchored && last_target.parent == source) {
    meeting.target_anchored = false;
    meeting.source_count = 0;
  }
  return meeting;
}

// Fills `out` with the steps of one side; false when a dynamic edge among them has changed
// parent within its history (the tree at `stamp` may not be the paths'), or has no data at
// `stamp` (0: both checked later, and each edge's newest stamp added to `common_newest`).
// The paths were built with each edge's newest parent.
bool takeSteps(const RootStep* steps, std::size_t count, bool last_anchored, std::int64_t stamp,
               bool prefetch, QuickStep* out, CommonNewest& common_newest) {
  for (std::size_t i = 0; i < count; ++i) {
    const RootStep& step = steps[i];
    QuickStep& quick = out[i];
    quick = QuickStep{step.cache, step.fixed, false, detail::TimeCache::kNoHint};
    if (!step.cache) continue;
    const detail::TimeCache& cache = *step.cache;
    quick.anchored = i + 1 == count ? last_anchored : step.anchored;
    if (stamp == 0) {
      common_newest.add(cache.newestStamp());
      continue;
    }
    if (stamp < cache.singleParentFrom() || stamp > cache.newestStamp()) return false;
    if (prefetch) quick.hint = cache.prefetch(stamp, quick.anchored);
  }
  return true;
}

// A path as a quick lookup takes it: the steps up from the source, then those up from the
// target, and the time to sample them at.
struct QuickPath {
  std::size_t source_count;
  std::size_t target_count;
  std::int64_t at;
  QuickStep steps[kMostSteps];
};

// Plans the lookup of `source` in `target` at `stamp` (0: the latest common time, which `at`
// then gives), starting the loads of the samples when `prefetch`; false when the root paths
// cannot answer.
bool planPath(const RootPaths& root_paths, const std::vector<FrameRecord>& frames, FrameId target,
              FrameId source, std::int64_t stamp, bool prefetch, QuickPath& path) {
  RootPaths::Path up_from_source;
  RootPaths::Path up_from_target;
  if (!root_paths.find(frames, source, up_from_source) ||
      !root_paths.find(frames, target, up_from_target) ||
      up_from_source.root != up_from_target.root) {
    return false;
  }
  const MeetingPoint meeting = meetingPoint(up_from_source, up_from_target, source, target);
  const std::size_t count = meeting.source_count + meeting.target_count;
  if (count > kMostSteps) return false;
  QuickStep* const steps = path.steps;
  prefetch = prefetch && stamp != 0;
  CommonNewest common_newest;
  if (!takeSteps(up_from_source.steps, meeting.source_count, meeting.source_anchored, stamp,
                 prefetch, steps, common_newest) ||
      !takeSteps(up_from_target.steps, meeting.target_count, meeting.target_anchored, stamp,
                 prefetch, steps + meeting.source_count, common_newest)) {
    return false;
  }
  path.source_count = meeting.source_count;
  path.target_count = meeting.target_count;
  path.at = stamp;
  if (stamp != 0 || !common_newest.any_dynamic) return true;
  const std::int64_t at = common_newest.stamp;
  for (std::size_t i = 0; i < count; ++i) {
    QuickStep& step = steps[i];
    if (!step.cache) continue;
    if (at < step.cache->singleParentFrom()) return false;
    step.hint = step.cache->hintNearNewest(at);
  }
  path.at = at;
  return true;
}

// The path's target_T_source from the value of each of its steps.
void productOf(const QuickPath& path, const Transform* const* values, Transform& target_T_source) {
  detail::pathProduct(values, path.source_count, values + path.source_count, path.target_count,
                      target_T_source);
}

// The values of the steps of one or more paths, with the interpolations they need run in one
// batch.
template <std::size_t Paths>
class PathSampler {
 public:
  /// Points `values` at the value of each of `path`'s steps, valid once run() has returned.
  void sample(const QuickPath& path, const Transform** values) {
    const std::size_t count = path.source_count + path.target_count;
    std::size_t task_count = count_;
    for (std::size_t i = 0; i < count; ++i) {
      const QuickStep& step = path.steps[i];
      if (!step.cache) {
        values[i] = step.fixed;
        continue;
      }
      const detail::SampleSpan span = step.cache->spanWithin(path.at, step.hint, step.anchored);
      if (!span.newer) {
        values[i] = span.older;
        continue;
      }
      Transform* out = ::new (static_cast<void*>(rooms_[task_count].bytes)) Transform;
      tasks_[task_count++] = {span.older, span.newer, span.ratio, out, span.arc_squared};
      values[i] = out;
    }
    count_ = task_count;
  }
  void run() const { detail::interpolateBatch(tasks_, count_); }

 private:
  detail::InterpolationTask tasks_[Paths * kMostSteps];
  TransformRoom rooms_[Paths * kMostSteps];
  std::size_t count_ = 0;
};

}  // namespace

bool BufferCore::Impl::quickLookup(FrameId target, FrameId source, std::int64_t& stamp,
                                   Transform* value) const {
  QuickPath path;
  if (!planPath(root_paths_, frames_, target, source, stamp, value != nullptr, path)) {
    return false;
  }
  if (value) {
    PathSampler<1> sampler;
    const Transform* values[kMostSteps];
    sampler.sample(path, values);
    sampler.run();
    productOf(path, values, *value);
  }
  stamp = path.at;
  return true;
}

bool BufferCore::Impl::quickTimeTravel(FrameId target, std::int64_t& target_stamp, FrameId source,
                                       std::int64_t& source_stamp, FrameId fixed,
                                       Transform& value) const {
  if (source == fixed || target == fixed) return false;
  QuickPath source_path;
  QuickPath target_path;
  if (!planPath(root_paths_, frames_, fixed, source, source_stamp, true, source_path) ||
      !planPath(root_paths_, frames_, target, fixed, target_stamp, true, target_path)) {
    return false;
  }
  PathSampler<2> sampler;
  const Transform* source_values[kMostSteps];
  const Transform* target_values[kMostSteps];
  sampler.sample(source_path, source_values);
  sampler.sample(target_path, target_values);
  sampler.run();
  Transform fixed_T_source;
  Transform target_T_fixed;
  productOf(source_path, source_values, fixed_T_source);
  productOf(target_path, target_values, target_T_fixed);
  value = detail::composed(target_T_fixed, fixed_T_source);
  source_stamp = source_path.at;
  target_stamp = target_path.at;
  return true;
}

}  // namespace lcmtf
