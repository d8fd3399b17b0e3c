// Four-lane values pass only between functions inlined into interpolateBatch(), so no call
// with them crosses the ABI GCC warns about for builds without AVX.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "batch_interpolation.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "compose.hpp"
#include "slerp_weights.hpp"
#include "wide_vectors.hpp"

namespace lcmtf::detail {

namespace {

// Four lanes of doubles, one register wide where the processor has AVX2.
using Four = double __attribute__((vector_size(4 * sizeof(double))));
using FourBits = std::int64_t __attribute__((vector_size(4 * sizeof(double))));
constexpr std::size_t kLanes = 4;

[[gnu::always_inline]] inline Four loadFour(const double* values) {
  Four four;
  std::memcpy(&four, values, sizeof four);
  return four;
}

[[gnu::always_inline]] inline void storeFour(double* values, Four four) {
  std::memcpy(values, &four, sizeof four);
}

// The slerp weights of a task whose arc was not worked out beforehand, or is too long for the
// short series.
void weightsOfAnyArc(const InterpolationTask& task, double& weight_a, double& weight_b) {
  const Eigen::Vector4d& a = task.older->rotation.coeffs();
  const Eigen::Vector4d& b = task.newer->rotation.coeffs();
  const bool far = a.dot(b) < 0.0;
  const double y = 0.25 * (far ? Eigen::Vector4d(a + b) : Eigen::Vector4d(a - b)).squaredNorm();
  weight_a = 1.0 - task.ratio;
  weight_b = task.ratio;
  slerpWeights(y, weight_a, weight_b);
  if (far) weight_b = -weight_b;
}

[[gnu::always_inline]] inline void blend(const InterpolationTask& task, double weight_a,
                                         double weight_b) {
  const Transform& older = *task.older;
  const Transform& newer = *task.newer;
  Transform& out = *task.out;
  if (task.ratio == 0.0) {
    out = older;
    return;
  }
  if (task.ratio == 1.0) {
    out = newer;
    return;
  }
  out.translation = older.translation + task.ratio * (newer.translation - older.translation);
  // Stored rotations are unit to rounding and the weights exact, so the sum is unit too.
  storeFour(out.rotation.coeffs().data(), weight_a * loadFour(older.rotation.coeffs().data()) +
                                              weight_b * loadFour(newer.rotation.coeffs().data()));
}

// Up to four tasks at once (`live` of them, the lanes after them idle): the weights of all four
// from the short series side by side, a negative weight for each newer rotation on the far
// side of the sphere from its older one.
[[gnu::always_inline]] inline void interpolateFour(const InterpolationTask* tasks,
                                                   std::size_t live) {
  Four ratio = {0.5, 0.5, 0.5, 0.5};
  Four known = {0.0, 0.0, 0.0, 0.0};
  for (std::size_t lane = 0; lane < kLanes; ++lane) {
    if (lane < live) {
      ratio[lane] = tasks[lane].ratio;
      known[lane] = tasks[lane].arc_squared;
    }
  }
  const FourBits far_side = reinterpret_cast<FourBits>(known) < 0;
  const Four arc_squared = far_side ? -known : known;
  const Four inverse_sinc = shortInverseSinc(arc_squared);
  const Four weight_a = shortSeriesWeight(1.0 - ratio, arc_squared, inverse_sinc);
  const Four near_weight_b = shortSeriesWeight(ratio, arc_squared, inverse_sinc);
  const Four weight_b = far_side ? -near_weight_b : near_weight_b;
  for (std::size_t lane = 0; lane < live; ++lane) {
    const InterpolationTask& task = tasks[lane];
    if (std::isnan(task.arc_squared)) {
      double any_a;
      double any_b;
      weightsOfAnyArc(task, any_a, any_b);
      blend(task, any_a, any_b);
    } else {
      blend(task, weight_a[lane], weight_b[lane]);
    }
  }
}

}  // namespace

LCMTF_WIDE_VECTORS void interpolateBatch(const InterpolationTask* tasks, std::size_t count) {
  std::size_t first = 0;
  for (; first + kLanes <= count; first += kLanes) interpolateFour(tasks + first, kLanes);
  if (first < count) interpolateFour(tasks + first, count - first);
  for (std::size_t i = 0; i < count; ++i) {
    const InterpolationTask& task = tasks[i];
    if (task.anchor) *task.out = composed(*task.anchor, *task.out);
  }
}

}  // namespace lcmtf::detail
