#include "batch_interpolation.hpp"

#include <algorithm>
#include <cmath>

#include "slerp_weights.hpp"
#include "wide_vectors.hpp"

namespace lcmtf::detail {

namespace {

constexpr std::size_t kLanes = 16;

[[gnu::always_inline]] inline void interpolateLanes(const InterpolationTask* tasks,
                                                    std::size_t count) {
  Eigen::Vector4d far_side[kLanes];  // each newer rotation on its older one's side of the sphere
  double y[kLanes];
  double weight_a[kLanes];
  double weight_b[kLanes];
  double arc_squared[kLanes];
  double inverse_sinc[kLanes];

  // y is kept at 0 for an arc already known, since only short arcs are given.
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector4d& a = tasks[i].older->rotation.coeffs();
    const double known_arc = tasks[i].arc_squared;
    far_side[i] = tasks[i].newer->rotation.coeffs();
    if (known_arc == known_arc) {
      if (std::signbit(known_arc)) far_side[i] = -far_side[i];
      arc_squared[i] = std::fabs(known_arc);
      y[i] = 0.0;
    } else {
      if (a.dot(far_side[i]) < 0.0) far_side[i] = -far_side[i];
      y[i] = 0.25 * (a - far_side[i]).squaredNorm();
      if (y[i] <= kShortSeriesLimit) arc_squared[i] = shortArcSquared(y[i]);
    }
    weight_a[i] = 1.0 - tasks[i].ratio;
    weight_b[i] = tasks[i].ratio;
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (y[i] <= kShortSeriesLimit) inverse_sinc[i] = shortInverseSinc(arc_squared[i]);
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (y[i] <= kShortSeriesLimit) {
      weight_a[i] = shortSeriesWeight(weight_a[i], arc_squared[i], inverse_sinc[i]);
      weight_b[i] = shortSeriesWeight(weight_b[i], arc_squared[i], inverse_sinc[i]);
    } else {
      slerpWeights(y[i], weight_a[i], weight_b[i]);
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    const InterpolationTask& task = tasks[i];
    const double ratio = task.ratio;
    Transform& out = *task.out;
    if (ratio == 0.0) {
      out = *task.older;
    } else if (ratio == 1.0) {
      out = *task.newer;
    } else {
      out.translation =
          task.older->translation + ratio * (task.newer->translation - task.older->translation);
      // Stored rotations are unit to rounding and the weights exact, so the sum is unit too.
      out.rotation.coeffs() =
          weight_a[i] * task.older->rotation.coeffs() + weight_b[i] * far_side[i];
    }
  }
}

}  // namespace

LCMTF_WIDE_VECTORS void interpolateBatch(const InterpolationTask* tasks, std::size_t count) {
  for (std::size_t first = 0; first < count; first += kLanes) {
    interpolateLanes(tasks + first, std::min(kLanes, count - first));
  }
}

}  // namespace lcmtf::detail
