// Four-lane values pass only between functions inlined into interpolateBatch(), so no call
// with them crosses the ABI GCC warns about for builds without AVX.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "batch_interpolation.hpp"

#include <cmath>

#include "slerp_weights.hpp"
#include "wide_transform.hpp"
#include "wide_vectors.hpp"

namespace lcmtf::detail {

namespace {

constexpr std::size_t kLanes = 4;

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

// The task's interpolated value, composed under its anchor when it has one, written to its
// room once. The value stays in registers in between, not written and read back for the
// anchor.
[[gnu::always_inline]] inline void blend(const InterpolationTask& task, double weight_a,
                                         double weight_b) {
  WideTransform value = widened(*task.older);
  if (task.ratio == 1.0) {
    value = widened(*task.newer);
  } else if (task.ratio != 0.0) {
    const WideTransform newer = widened(*task.newer);
    value.translation += task.ratio * (newer.translation - value.translation);
    // Stored rotations are unit to rounding and the weights exact, so the sum is unit too.
    value.rotation = weight_a * value.rotation + weight_b * newer.rotation;
  }
  if (task.anchor) value = composedWide(widened(*task.anchor), value);
  storeWide(value, *task.out);
}

// Lane `Lane`'s task blended with that lane's weights, or with its own where its arc was not
// worked out beforehand. The lane is named at compile time, so that its weights come straight
// out of their registers, where a loop over the lanes read them back through memory: 1-4 % off
// the lookups of buffer_core_bench on pr2, deep_chain and wide.
template <std::size_t Lane>
[[gnu::always_inline]] inline void blendLane(const InterpolationTask* tasks, Four weight_a,
                                             Four weight_b) {
  const InterpolationTask& task = tasks[Lane];
  if (std::isnan(task.arc_squared)) {
    double any_a;
    double any_b;
    weightsOfAnyArc(task, any_a, any_b);
    blend(task, any_a, any_b);
  } else {
    blend(task, weight_a[Lane], weight_b[Lane]);
  }
}

// Up to four tasks at once (`live` of them, at least one, the lanes after them idle): the weights
// of all four from the short series side by side, a negative weight for each newer rotation on the
// far side of the sphere from its older one.
[[gnu::always_inline]] inline void interpolateFour(const InterpolationTask* tasks,
                                                   std::size_t live) {
  // Idle lanes repeat the first task. Inserted into zeros instead, the first lane took an
  // instruction (a register form of VEX vmovq) that Valgrind 3.19 cannot run.
  Four ratio = {tasks[0].ratio, tasks[0].ratio, tasks[0].ratio, tasks[0].ratio};
  Four known = {tasks[0].arc_squared, tasks[0].arc_squared, tasks[0].arc_squared,
                tasks[0].arc_squared};
  for (std::size_t lane = 1; lane < kLanes; ++lane) {
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
  blendLane<0>(tasks, weight_a, weight_b);
  if (live > 1) blendLane<1>(tasks, weight_a, weight_b);
  if (live > 2) blendLane<2>(tasks, weight_a, weight_b);
  if (live > 3) blendLane<3>(tasks, weight_a, weight_b);
}

}  // namespace

LCMTF_WIDE_VECTORS void interpolateBatch(const InterpolationTask* tasks, std::size_t count) {
  std::size_t first = 0;
  for (; first + kLanes <= count; first += kLanes) interpolateFour(tasks + first, kLanes);
  if (first < count) interpolateFour(tasks + first, count - first);
}

}  // namespace lcmtf::detail
