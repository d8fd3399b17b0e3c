#include "path_product.hpp"

#include <algorithm>

#include "compose.hpp"
#include "wide_vectors.hpp"

namespace lcmtf::detail {

namespace {

// top_T_bottom of `count` step values, bottom step first, composed from the top down:
// product = product * step. Each step then only waits on the rotation composed so far, while
// the translations rotate into place alongside and add up at the end of the chain. A long
// chain is cut into up to four runs composed side by side, so that the processor works on four
// rotations at once rather than waiting on each in turn; the runs' products compose at the end
// (the root <-> deepest leaf rows of buffer_core_bench, on paths of 27 and 32 edges).
[[gnu::always_inline]] inline Transform chainProduct(const Transform* const* values,
                                                     std::size_t count) {
  constexpr std::size_t kMostRuns = 4;
  constexpr std::size_t kShortestSplit = 8;
  if (count == 0) return Transform::identity();
  if (count < kShortestSplit) {
    Transform product = *values[count - 1];
    for (std::size_t i = count - 1; i-- > 0;) composeUnder(product, *values[i]);
    return product;
  }
  const std::size_t length = (count + kMostRuns - 1) / kMostRuns;
  const std::size_t runs = (count + length - 1) / length;
  Transform run_products[kMostRuns];
  std::size_t run_tops[kMostRuns];
  for (std::size_t r = 0; r < runs; ++r) {
    run_tops[r] = std::min(count, (r + 1) * length) - 1;
    run_products[r] = *values[run_tops[r]];
  }
  for (std::size_t step = 1; step < length; ++step) {
    for (std::size_t r = 0; r < runs; ++r) {
      const std::size_t bottom = r * length;
      if (run_tops[r] >= bottom + step) composeUnder(run_products[r], *values[run_tops[r] - step]);
    }
  }
  Transform product = run_products[runs - 1];
  for (std::size_t r = runs - 1; r-- > 0;) composeUnder(product, run_products[r]);
  return product;
}

}  // namespace

LCMTF_WIDE_VECTORS void pathProduct(const Transform* const* up_from_source,
                                    std::size_t source_count,
                                    const Transform* const* up_from_target,
                                    std::size_t target_count, Transform& target_T_source) {
  const Transform ancestor_T_source = chainProduct(up_from_source, source_count);
  const Transform ancestor_T_target = chainProduct(up_from_target, target_count);
  // target_T_ancestor * ancestor_T_source, without forming the inverse.
  const Eigen::Quaterniond target_R_ancestor = ancestor_T_target.rotation.conjugate();
  target_T_source.translation =
      rotated(target_R_ancestor, ancestor_T_source.translation - ancestor_T_target.translation);
  target_T_source.rotation = target_R_ancestor * ancestor_T_source.rotation;
}

}  // namespace lcmtf::detail
