#include "path_product.hpp"

#include "compose.hpp"
#include "wide_vectors.hpp"

namespace lcmtf::detail {

namespace {

// top_T_bottom of `count` step values, bottom step first, composed from the top down:
// product = product * step. Each step then only waits on the rotation composed so far, while
// the translations rotate into place alongside and add up at the end of the chain.
[[gnu::always_inline]] inline Transform chainProduct(const Transform* const* values,
                                                     std::size_t count) {
  if (count == 0) return Transform::identity();
  Transform product = *values[count - 1];
  for (std::size_t i = count - 1; i-- > 0;) composeUnder(product, *values[i]);
  return product;
}

}  // namespace

LCMTF_WIDE_VECTORS void pathProduct(const Transform* const* up_from_source,
                                    std::size_t source_count,
                                    const Transform* const* up_from_target,
                                    std::size_t target_count, Transform& target_T_source) {
  // Where the target is above the source (as for a root), its side is the identity: composing
  // with it would only lengthen the chain the answer waits on.
  if (target_count == 0) {
    target_T_source = chainProduct(up_from_source, source_count);
    return;
  }
  const Transform ancestor_T_source = chainProduct(up_from_source, source_count);
  const Transform ancestor_T_target = chainProduct(up_from_target, target_count);
  // target_T_ancestor * ancestor_T_source, without forming the inverse.
  const Eigen::Quaterniond target_R_ancestor = ancestor_T_target.rotation.conjugate();
  target_T_source.translation =
      rotated(target_R_ancestor, ancestor_T_source.translation - ancestor_T_target.translation);
  target_T_source.rotation = target_R_ancestor * ancestor_T_source.rotation;
}

}  // namespace lcmtf::detail
