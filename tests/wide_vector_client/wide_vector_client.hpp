#pragma once

// Calls into lcmtf from code built with AVX2 (-mavx2 -mfma), where Eigen aligns its
// quaternions to 32 bytes rather than the 16 of a plain x86-64 build, as a program built with
// -march=native meets the library. Call only where the processor has AVX2 and FMA.

#include <cstddef>

#include "lcmtf/transform_stamped.hpp"

namespace lcmtf::test {

/// Sizes and member offsets of the public structs as code built with AVX2 sees them.
struct Layout {
  std::size_t transform_size;
  std::size_t transform_alignment;
  std::size_t transform_rotation_offset;
  std::size_t stamped_size;
  std::size_t stamped_alignment;
  std::size_t stamped_transform_offset;
  std::size_t pose_with_covariance_size;
  std::size_t pose_with_covariance_covariance_offset;
};
Layout layoutSeenWithWideVectors();

/// Fills a BufferCore from code built with AVX2 (map -> odom dynamic, odom -> base_link
/// static, at 0 and 1 s) and looks up base_link in map at 0.25 s there.
TransformStamped lookupWithWideVectors();

}  // namespace lcmtf::test
