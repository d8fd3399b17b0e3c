#include "lcmtf/transform_validation.hpp"

#include <cmath>

#include "lcmtf/frame_name.hpp"
#include "name_words.hpp"
#include "transform_check.hpp"

namespace lcmtf {

namespace {

std::string edgeName(const TransformStamped& t) {
  return "'" + t.parent_frame + "' -> '" + t.child_frame + "' at " + toString(t.stamp);
}

}  // namespace

InsertRejection detail::checkTransformFully(const TransformStamped& transform,
                                            double& rotation_norm, std::string& reason) {
  const std::string_view parent = canonicalFrameName(transform.parent_frame);
  const std::string_view child = canonicalFrameName(transform.child_frame);
  const Transform& value = transform.transform;
  rotation_norm = 1.0;
  // Most rotations are unit to a few ulps, and then their norm is not needed.
  const double squared_norm = value.rotation.squaredNorm();
  const bool plainly_unit = unitToRounding(squared_norm);
  const double norm = plainly_unit ? 1.0 : std::sqrt(squared_norm);
  if (parent.empty() || child.empty()) {
    reason = "empty " + std::string(child.empty() ? "child" : "parent") + " frame name in " +
             edgeName(transform);
    return InsertRejection::kEmptyFrameName;
  }
  if (detail::sameName(parent, child)) {
    reason = "frame '" + std::string(child) + "' cannot be its own parent";
    return InsertRejection::kSelfParented;
  }
  if (!value.translation.allFinite() || !value.rotation.coeffs().allFinite()) {
    reason = "NaN or infinite value in " + edgeName(transform);
    return InsertRejection::kNonFinite;
  }
  if (norm == 0.0 || std::abs(norm - 1.0) > 1e-3) {
    reason = "quaternion of norm " + std::to_string(norm) + " in " + edgeName(transform) +
             " (must be within 1e-3 of 1)";
    return InsertRejection::kBadQuaternion;
  }
  // A unit quaternion computed in double precision is often a few ulps off 1: that is not
  // denormalized input, so it is stored as given and not counted.
  if (!plainly_unit && std::abs(norm - 1.0) > kUnitNormRounding) rotation_norm = norm;
  return InsertRejection::kCount;
}

InsertRejection validateTransform(const TransformStamped& transform, Transform& value,
                                  bool& normalized, std::string& reason) {
  double norm = 1.0;
  const InsertRejection rejection = detail::checkTransform(transform, norm, reason);
  normalized = norm != 1.0;
  value = normalized ? detail::normalizedBy(transform.transform, norm) : transform.transform;
  return rejection;
}

InsertRejection validateTransform(const TransformStamped& transform, std::string* reason) {
  Transform value;
  bool normalized = false;
  std::string why;
  const InsertRejection rejection = validateTransform(transform, value, normalized, why);
  if (reason) *reason = std::move(why);
  return rejection;
}

}  // namespace lcmtf
