#pragma once

#include <cstddef>

#include "path_plan.hpp"

namespace lcmtf::detail {

/// Longer paths are left to the walk, so that a quick lookup needs no heap.
constexpr std::size_t kMostQuickSteps = 64;

/// A plan as a quick lookup makes it, with room for its steps.
struct QuickPath {
  PathPlan plan;
  PlanStep steps[kMostQuickSteps];
};

}  // namespace lcmtf::detail
