// Four-lane values pass only between functions inlined into interpolateBatch(), so no call
// with them crosses the ABI GCC warns about for builds without AVX.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "batch_interpolation.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>

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

// Four tasks at once: the weights of all four from the short series side by side, a negative
// weight for each newer rotation on the far side of the sphere from its older one.
[[gnu::always_inline]] inline void interpolateFour(const InterpolationTask* const* lanes) {
  const Four ratio = {lanes[0]->ratio, lanes[1]->ratio, lanes[2]->ratio, lanes[3]->ratio};
  const Four known = {lanes[0]->arc_squared, lanes[1]->arc_squared, lanes[2]->arc_squared,
                      lanes[3]->arc_squared};
  const FourBits far_side = reinterpret_cast<FourBits>(known) < 0;
  const Four arc_squared = far_side ? -known : known;
  const Four inverse_sinc = shortInverseSinc(arc_squared);
  const Four weight_a = shortSeriesWeight(1.0 - ratio, arc_squared, inverse_sinc);
  const Four near_weight_b = shortSeriesWeight(ratio, arc_squared, inverse_sinc);
  const Four weight_b = far_side ? -near_weight_b : near_weight_b;
  for (std::size_t lane = 0; lane < kLanes; ++lane) {
    const InterpolationTask& task = *lanes[lane];
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

// Room for a transform nobody reads.
struct Scratch {
  alignas(Transform) unsigned char bytes[sizeof(Transform)];
};

}  // namespace

LCMTF_WIDE_VECTORS void interpolateBatch(const InterpolationTask* tasks, std::size_t count) {
  std::size_t first = 0;
  for (; first + kLanes <= count; first += kLanes) {
    const InterpolationTask* const lanes[kLanes] = {tasks + first, tasks + first + 1,
                                                    tasks + first + 2, tasks + first + 3};
    interpolateFour(lanes);
  }
  if (first == count) return;
  // Lanes to spare interpolate the last task's older value with itself, into scratch.
  Scratch scratch;
  const InterpolationTask& last = tasks[count - 1];
  const InterpolationTask spare{last.older, last.older, 0.5,
                                ::new (static_cast<void*>(scratch.bytes)) Transform, 0.0};
  const InterpolationTask* lanes[kLanes];
  for (std::size_t lane = 0; lane < kLanes; ++lane) {
    lanes[lane] = first + lane < count ? tasks + first + lane : &spare;
  }
  interpolateFour(lanes);
}

}  // namespace lcmtf::detail
