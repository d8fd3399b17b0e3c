#include "path_product.hpp"

#include <algorithm>

#include "compose.hpp"

namespace lcmtf::detail {

namespace {

// The product top_T_bottom of `count` step values, bottom step first.
struct ChainProduct {
  const Transform* const* first;
  std::size_t count;
  Transform value;
};

}  // namespace

// Each side's lower and upper halves are four independent chains of products, composed in
// one loop so that their long dependent arithmetic overlaps; the halves are joined after.
Transform pathProduct(const Transform* const* up_from_source, std::size_t source_count,
                      const Transform* const* up_from_target, std::size_t target_count) {
  const std::size_t source_low = source_count / 2;
  const std::size_t target_low = target_count / 2;
  ChainProduct chains[4] = {
      {up_from_source, source_low, Transform::identity()},
      {up_from_source + source_low, source_count - source_low, Transform::identity()},
      {up_from_target, target_low, Transform::identity()},
      {up_from_target + target_low, target_count - target_low, Transform::identity()}};
  const std::size_t longest = std::max(source_count - source_low, target_count - target_low);
  for (std::size_t i = 0; i < longest; ++i) {
    for (ChainProduct& chain : chains) {
      if (i < chain.count) composeOnto(*chain.first[i], chain.value);
    }
  }
  composeOnto(chains[1].value, chains[0].value);
  composeOnto(chains[3].value, chains[2].value);
  const Transform& ancestor_T_source = chains[0].value;
  const Transform& ancestor_T_target = chains[2].value;
  // target_T_ancestor * ancestor_T_source, without forming the inverse.
  const Eigen::Quaterniond target_R_ancestor = ancestor_T_target.rotation.conjugate();
  return Transform(
      rotated(target_R_ancestor, ancestor_T_source.translation - ancestor_T_target.translation),
      target_R_ancestor * ancestor_T_source.rotation);
}

}  // namespace lcmtf::detail
