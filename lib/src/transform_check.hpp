#pragma once

#include <cmath>
#include <string>

#include "lcmtf/frame_name.hpp"
#include "lcmtf/insert_statistics.hpp"
#include "lcmtf/transform_stamped.hpp"
#include "name_words.hpp"

namespace lcmtf::detail {

/// How far from 1 the norm, or the squared norm, of a unit quaternion computed in double
/// precision may be.
constexpr double kUnitNormRounding = 1e-12;

/// Whether a rotation of `squared_norm` is unit to rounding: stored as given, and finite.
inline bool unitToRounding(double squared_norm) {
  return std::abs(squared_norm - 1.0) <= kUnitNormRounding;
}

/// Whether `transform` passes every check with its rotation unit to rounding, found with few
/// instructions and branches: a rotation that close to unit is finite, and a translation is
/// finite when each coordinate times zero is zero (infinity or NaN times zero is NaN). Inline,
/// in place of every check out of line: the inserts of buffer_core_bench on pr2 and deep_chain
/// 58 -> 53 ns (with saturatingSubtract() by the overflow builtin, 801 instructions where they
/// took 888).
inline bool isPlainlyValid(const TransformStamped& transform) {
  const std::string_view parent = canonicalFrameName(transform.parent_frame);
  const std::string_view child = canonicalFrameName(transform.child_frame);
  const Transform& value = transform.transform;
  const Eigen::Vector3d& t = value.translation;
  const double zero_if_finite = t.x() * 0.0 + t.y() * 0.0 + t.z() * 0.0;
  return unitToRounding(value.rotation.squaredNorm()) && zero_if_finite == 0.0 && !parent.empty() &&
         !child.empty() && !sameName(parent, child);
}

/// checkTransform() for a transform that is not plainly valid: why it is refused, or how much
/// to scale its rotation by.
InsertRejection checkTransformFully(const TransformStamped& transform, double& rotation_norm,
                                    std::string& reason);

/// validateTransform()'s checks, without copying the transform: `rotation_norm` is what to
/// divide its rotation by before storing it, 1 when it is stored as given. Copying only the
/// rotations to normalize made the inserts of buffer_core_bench 1-2 % faster on pr2, deep_chain
/// and wide (the forest's did not change).
inline InsertRejection checkTransform(const TransformStamped& transform, double& rotation_norm,
                                      std::string& reason) {
  rotation_norm = 1.0;
  if (isPlainlyValid(transform)) return InsertRejection::kCount;
  return checkTransformFully(transform, rotation_norm, reason);
}

/// `value` with its rotation divided by the `rotation_norm` checkTransform() gave.
inline Transform normalizedBy(const Transform& value, double rotation_norm) {
  Transform normalized = value;
  normalized.rotation.coeffs() /= rotation_norm;
  return normalized;
}

}  // namespace lcmtf::detail
