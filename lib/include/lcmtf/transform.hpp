#pragma once

#include <Eigen/Geometry>

namespace lcmtf {

/// A rigid transform parent_T_child: rotation (unit quaternion) then translation.
/// Compose so the frame names cancel: a_T_c = a_T_b * b_T_c.
///
/// Aligned to 32 bytes whatever instructions Eigen vectorizes with: Eigen aligns a quaternion
/// to 16 bytes under SSE and to 32 under AVX, so without this a program built with -mavx or
/// -march=native would lay out TransformStamped (and every struct holding a Transform)
/// differently from a library built for plain x86-64, and the two would read each other's
/// fields at the wrong offsets.
struct alignas(32) Transform {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();

  Transform() = default;
  Transform(const Eigen::Vector3d& translation_in, const Eigen::Quaterniond& rotation_in)
      : translation(translation_in), rotation(rotation_in) {}

  static Transform identity() { return Transform(); }

  /// child_T_parent from parent_T_child.
  Transform inverse() const {
    const Eigen::Quaterniond inverse_rotation = rotation.conjugate();
    return Transform(-(inverse_rotation * translation), inverse_rotation);
  }

  /// The rotation as a 3x3 matrix, scaled by 2/|q|^2: an unnormalized quaternion gives its
  /// rotation, and a rounded unit quaternion of a quarter turn gives exact zeros and ones.
  Eigen::Matrix3d rotationMatrix() const;

  /// A point given in the child frame, expressed in the parent frame: R p + t with R a matrix,
  /// so an infinite coordinate stays infinite wherever its column of R is non-zero.
  Eigen::Vector3d operator*(const Eigen::Vector3d& point) const {
    return rotationMatrix() * point + translation;
  }

  /// A direction given in the child frame, expressed in the parent frame (rotation only).
  Eigen::Vector3d rotate(const Eigen::Vector3d& vector) const { return rotationMatrix() * vector; }

  Transform operator*(const Transform& child_T_grandchild) const {
    return Transform(rotation * child_T_grandchild.translation + translation,
                     rotation * child_T_grandchild.rotation);
  }

  Eigen::Isometry3d toIsometry() const;
  /// Takes the rotation part as orthonormal and renormalizes the resulting quaternion.
  static Transform fromIsometry(const Eigen::Isometry3d& isometry);

  /// True when translations differ by at most `tolerance` metres and rotations by at most
  /// `tolerance` radians (q and -q are the same rotation).
  bool isApprox(const Transform& other, double tolerance = 1e-12) const;
};

static_assert(sizeof(Transform) == 64 && alignof(Transform) == 32,
              "lcmtf::Transform must have one layout in every program that uses the library");

/// Shortest-arc spherical interpolation: `a` at ratio 0, `b` (or -b) at ratio 1, unit length
/// between.
Eigen::Quaterniond slerp(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double ratio);

/// Linear interpolation of translation and slerp of rotation; exact at ratio 0 and 1.
Transform interpolate(const Transform& a, const Transform& b, double ratio);

/// The angle in radians of the rotation taking `a` to `b`, in [0, pi].
double angularDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

}  // namespace lcmtf
