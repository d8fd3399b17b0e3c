#pragma once

#include <cstddef>
#include <cstdint>
#include <new>

#include "batch_interpolation.hpp"
#include "path_product.hpp"
#include "time_cache.hpp"

namespace lcmtf::detail {

/// A step of a planned path: a static value, or a dynamic edge's history to sample. Left
/// uninitialized in arrays sized for the longest path; planners set every field.
struct PlanStep {
  const TimeCache* cache;   // null for a static step
  const Transform* fixed;   // a static step's value
  const Transform* anchor;  // the static chain above the edge's parent, composed onto its value;
                            // null for none
  bool single_parent;       // every sample the time may fall between has the edge's newest parent
  std::size_t hint;         // where the samples likely are (TimeCache::prefetch), or kNoHint
};

/// A lookup's path, whichever way it was found (the root paths or the walk): the steps up from
/// the source to where the two frames' ways meet, then those up from the target, and the time
/// at which the dynamic steps are sampled. Every dynamic step has data at `at`.
struct PathPlan {
  const PlanStep* steps = nullptr;
  std::size_t source_count = 0;
  std::size_t target_count = 0;
  std::int64_t at = 0;

  std::size_t size() const { return source_count + target_count; }
};

/// Room for a transform, constructed only when used.
struct TransformRoom {
  alignas(Transform) unsigned char bytes[sizeof(Transform)];
};

/// Storage a PathSampler works in: a task and a room for every step sampled.
struct SamplerStorage {
  InterpolationTask* tasks;
  TransformRoom* rooms;
};

/// The values of the steps of one or more plans, with the interpolations they need run in one
/// batch, in storage the caller gives.
class PathSampler {
 public:
  explicit PathSampler(const SamplerStorage& storage) : storage_(storage) {}

  /// Points `values` at the value of each of `plan`'s steps, valid once run() has returned.
  void sample(const PathPlan& plan, const Transform** values) {
    const std::size_t count = plan.size();
    for (std::size_t i = 0; i < count; ++i) {
      const PlanStep& step = plan.steps[i];
      if (!step.cache) {
        values[i] = step.fixed;
        continue;
      }
      SampleSpan span;
      if (step.single_parent) {
        span = step.cache->spanWithin(plan.at, step.hint);
      } else {
        step.cache->find(plan.at, span);
      }
      values[i] = take(span, step.anchor);
    }
  }
  /// The value of a step whose samples are `span`, composed onto `anchor` unless null: the
  /// older sample itself when exact and unanchored, else a room that run() fills.
  const Transform* take(const SampleSpan& span, const Transform* anchor) {
    if (!span.newer && !anchor) return span.older;
    Transform* out = ::new (static_cast<void*>(storage_.rooms[rooms_++].bytes)) Transform;
    // An exact sample to anchor is a task at ratio 0, so that every anchor is composed in
    // the batch's wide instructions: 2-4 % of each lookup on pr2 in buffer_core_bench.
    storage_.tasks[tasks_++] =
        span.newer
            ? InterpolationTask{span.older, span.newer, span.ratio, out, span.arc_squared, anchor}
            : InterpolationTask{span.older, span.older, 0.0, out, 0.0, anchor};
    return out;
  }
  std::size_t taskCount() const { return tasks_; }
  void run() const { interpolateBatch(storage_.tasks, tasks_); }

 private:
  SamplerStorage storage_;
  std::size_t tasks_ = 0;
  std::size_t rooms_ = 0;
};

/// The plan's target_T_source from the value of each of its steps (sampled by PathSampler).
inline void productOf(const PathPlan& plan, const Transform* const* values,
                      Transform& target_T_source) {
  pathProduct(values, plan.source_count, values + plan.source_count, plan.target_count,
              target_T_source);
}

}  // namespace lcmtf::detail
