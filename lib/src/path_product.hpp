#pragma once

#include <cstddef>

#include "lcmtf/transform.hpp"

namespace lcmtf::detail {

/// target_T_source from the values of the steps up from each frame to where the two paths
/// meet (each list bottom step first): the product of the source's steps, composed with the
/// inverse of the product of the target's.
Transform pathProduct(const Transform* const* up_from_source, std::size_t source_count,
                      const Transform* const* up_from_target, std::size_t target_count);

}  // namespace lcmtf::detail
