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

/// Runs every task, with interpolate()'s result for each (for unit rotations), but four at a
/// time, the slerp weights of the four worked out side by side in vector registers.
void interpolateBatch(const InterpolationTask* tasks, std::size_t count);

}  // namespace lcmtf::detail
