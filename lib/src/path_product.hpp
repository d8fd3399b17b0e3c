#pragma once

#include <cstddef>

#include "lcmtf/transform.hpp"

namespace lcmtf::detail {

/// target_T_source from the values of the steps up from each frame to where the two paths
/// meet (each list bottom step first): the product of the source's steps, composed with the
/// inverse of the product of the target's. Written in place, so that the caller's copy does
/// not read a result still on its way to memory.
void pathProduct(const Transform* const* up_from_source, std::size_t source_count,
                 const Transform* const* up_from_target, std::size_t target_count,
                 Transform& target_T_source);

}  // namespace lcmtf::detail
