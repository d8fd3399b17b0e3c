#include "path_product.hpp"

#include "compose.hpp"
#include "wide_vectors.hpp"

namespace lcmtf::detail {

namespace {

// top_T_bottom of `count` step values, bottom step first. A long chain is composed as two
// halves side by side, so that their dependent arithmetic overlaps, and the halves joined.
[[gnu::always_inline]] inline Transform chainProduct(const Transform* const* values,
                                                     std::size_t count) {
  if (count == 0) return Transform::identity();
  if (count < 4) {
    Transform product = *values[0];
    for (std::size_t i = 1; i < count; ++i) composeOnto(*values[i], product);
    return product;
  }
  const std::size_t half = count / 2;
  Transform lower = *values[0];
  Transform upper = *values[half];
  for (std::size_t i = 1; i < half; ++i) {
    composeOnto(*values[i], lower);
    composeOnto(*values[half + i], upper);
  }
  if (count % 2 == 1) composeOnto(*values[count - 1], upper);
  composeOnto(upper, lower);
  return lower;
}

}  // namespace

LCMTF_WIDE_VECTORS Transform pathProduct(const Transform* const* up_from_source,
                                         std::size_t source_count,
                                         const Transform* const* up_from_target,
                                         std::size_t target_count) {
  const Transform ancestor_T_source = chainProduct(up_from_source, source_count);
  const Transform ancestor_T_target = chainProduct(up_from_target, target_count);
  // target_T_ancestor * ancestor_T_source, without forming the inverse.
  const Eigen::Quaterniond target_R_ancestor = ancestor_T_target.rotation.conjugate();
  return Transform(
      rotated(target_R_ancestor, ancestor_T_source.translation - ancestor_T_target.translation),
      target_R_ancestor * ancestor_T_source.rotation);
}

}  // namespace lcmtf::detail
