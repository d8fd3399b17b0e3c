// Four-lane values pass only between functions inlined into pathProduct(), so no call with
// them crosses the ABI GCC warns about for builds without AVX.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "path_product.hpp"

#include "wide_transform.hpp"
#include "wide_vectors.hpp"

namespace lcmtf::detail {

namespace {

// top_T_bottom of `count` step values, bottom step first, composed from the top down:
// product = product * step. Each step then only waits on the rotation composed so far, while
// the translations rotate into place alongside and add up at the end of the chain.
[[gnu::always_inline]] inline WideTransform chainProduct(const Transform* const* values,
                                                         std::size_t count) {
  if (count == 0) return widened(Transform::identity());
  WideTransform product = widened(*values[count - 1]);
  for (std::size_t i = count - 1; i-- > 0;) {
    const WideTransform step = widened(*values[i]);
    product.translation += rotatedWide(product.rotation, step.translation);
    product.rotation = quaternionProduct(product.rotation, step.rotation);
  }
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
    narrowInto(chainProduct(up_from_source, source_count), target_T_source);
    return;
  }
  const WideTransform ancestor_T_source = chainProduct(up_from_source, source_count);
  const WideTransform ancestor_T_target = chainProduct(up_from_target, target_count);
  // target_T_ancestor * ancestor_T_source, without forming the inverse.
  const Four target_R_ancestor = conjugate(ancestor_T_target.rotation);
  narrowInto(WideTransform{rotatedWide(target_R_ancestor, ancestor_T_source.translation -
                                                              ancestor_T_target.translation),
                           quaternionProduct(target_R_ancestor, ancestor_T_source.rotation)},
             target_T_source);
}

}  // namespace lcmtf::detail
