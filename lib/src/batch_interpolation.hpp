#pragma once

#include <cstddef>

#include "lcmtf/transform.hpp"

namespace lcmtf::detail {

/// One interpolation of a batch: interpolate(*older, *newer, ratio) goes to *out.
/// `arc_squared` is signedArcSquared(older rotation, newer rotation), or NaN to work it out.
struct InterpolationTask {
  const Transform* older;
  const Transform* newer;
  double ratio;
  Transform* out;
  double arc_squared;
};

/// Runs every task, with interpolate()'s result for each (for unit rotations), but stage by
/// stage across the batch so that the long chains of dependent arithmetic in each slerp overlap.
void interpolateBatch(const InterpolationTask* tasks, std::size_t count);

}  // namespace lcmtf::detail
