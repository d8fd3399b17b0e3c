#pragma once

#include <cstddef>

#include "lcmtf/transform.hpp"

namespace lcmtf::detail {

/// One interpolation of a batch: interpolate(*older, *newer, ratio) goes to *out, composed
/// under *anchor first when there is one (a static chain above the edge's parent).
/// `arc_squared` is signedArcSquared(older rotation, newer rotation), or NaN to work it out.
/// No field has a default: lookups keep tasks in arrays sized for the longest path, and a
/// default would fill every one of them on every lookup.
struct InterpolationTask {
  const Transform* older;
  const Transform* newer;
  double ratio;
  Transform* out;
  double arc_squared;
  const Transform* anchor;
};

/// Runs every task, with interpolate()'s result for each (for unit rotations), but four at a
/// time, the slerp weights of the four worked out side by side in vector registers. The
/// anchors are composed here too, in the same wide instructions.
void interpolateBatch(const InterpolationTask* tasks, std::size_t count);

}  // namespace lcmtf::detail
