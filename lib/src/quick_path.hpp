#pragma once

#include <cstddef>

#include "path_plan.hpp"

namespace lcmtf::detail {

/// Longer paths are left to the walk, so that a quick lookup needs no heap.
constexpr std::size_t kMostQuickSteps = 64;

/// A plan as a quick lookup makes it, with room for its steps.
struct QuickPlan {
  PathPlan plan;
  PlanStep steps[kMostQuickSteps];
};

/// A quick plan with room for working out its steps' values (`values`, pointing at static values
/// or into `rooms`, which `tasks` fill). A plan at the latest common time that took its samples
/// as it went (`sampled`) leaves `steps` unwritten and its plan's `steps` null: its values and
/// first `task_count` tasks are set already. A time-travel lookup's two plans, sampled together,
/// are QuickPlans: the rooms of two QuickPaths took 16 KiB more of a thread's stack.
struct QuickPath : QuickPlan {
  bool sampled = false;
  std::size_t task_count;
  const Transform* values[kMostQuickSteps];
  InterpolationTask tasks[kMostQuickSteps];
  const TimeCache* task_caches[kMostQuickSteps];  // the edge of each task
  std::size_t hints[kMostQuickSteps];             // TimeCache::prefetch() of each dynamic step
  TransformRoom rooms[kMostQuickSteps];
};

}  // namespace lcmtf::detail
