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
// the translations rotate into place alongside and add up at the end of the chain. (Two halves
// composed side by side, then joined, made deepest lookups 5-7 % faster and wide's 3-5 %
// slower.)
[[gnu::always_inline]] inline WideTransform chainProduct(const Transform* const* values,
                                                         std::size_t count) {
  if (count == 0) return widened(Transform::identity());
  WideTransform product = widened(*values[count - 1]);
  for (std::size_t i = count - 1; i-- > 0;) {
    product = composedUnderLastKnown(product, widened(*values[i]));
  }
  return product;
}

// target_T_ancestor * ancestor_T_source, without forming the inverse. Apart from
// pathProduct(): clang refuses four-lane arguments in calls made by a function it also compiles
// for processors without AVX, but not in the functions inlined into it.
[[gnu::always_inline]] inline void joinInto(const WideTransform& ancestor_T_source,
                                            const WideTransform& ancestor_T_target,
                                            Transform& target_T_source) {
  const Four target_R_ancestor = conjugate(ancestor_T_target.rotation);
  narrowInto(WideTransform{rotatedByLastKnown(target_R_ancestor, ancestor_T_source.translation -
                                                                     ancestor_T_target.translation),
                           quaternionProduct(target_R_ancestor, ancestor_T_source.rotation)},
             target_T_source);
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
  joinInto(chainProduct(up_from_source, source_count), chainProduct(up_from_target, target_count),
           target_T_source);
}

}  // namespace lcmtf::detail
