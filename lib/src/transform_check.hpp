#pragma once

#include <string>

#include "lcmtf/insert_statistics.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf::detail {

/// validateTransform()'s checks, without copying the transform: `rotation_norm` is what to
/// divide its rotation by before storing it, 1 when it is stored as given. Copying only the
/// rotations to normalize made the inserts of buffer_core_bench 1-2 % faster on pr2, deep_chain
/// and wide (the forest's did not change).
InsertRejection checkTransform(const TransformStamped& transform, double& rotation_norm,
                               std::string& reason);

/// `value` with its rotation divided by the `rotation_norm` checkTransform() gave.
inline Transform normalizedBy(const Transform& value, double rotation_norm) {
  Transform normalized = value;
  normalized.rotation.coeffs() /= rotation_norm;
  return normalized;
}

}  // namespace lcmtf::detail
