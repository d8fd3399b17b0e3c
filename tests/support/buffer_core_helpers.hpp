#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>

#include "lcmtf/buffer_core.hpp"

namespace lcmtf_test {

/// A fixed epoch for buffer tests, so that times in messages are predictable strings.
inline constexpr lcmtf::TimePoint kEpoch = lcmtf::fromUtime(1'700'000'000'000'000);

/// kEpoch plus `seconds`, rounded to the microsecond.
inline lcmtf::TimePoint at(double seconds) { return kEpoch + lcmtf::secondsToDuration(seconds); }

inline Eigen::Quaterniond axisAngle(double angle, const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

/// parent_T_child as a transform and as an independently built Eigen isometry.
inline lcmtf::Transform pose(const Eigen::Vector3d& translation, double angle,
                             const Eigen::Vector3d& axis) {
  return lcmtf::Transform(translation, axisAngle(angle, axis));
}
inline Eigen::Isometry3d isometry(const Eigen::Vector3d& translation, double angle,
                                  const Eigen::Vector3d& axis) {
  return Eigen::Translation3d(translation) * Eigen::AngleAxisd(angle, axis.normalized());
}

inline lcmtf::TransformStamped stamped(const std::string& parent, const std::string& child,
                                       lcmtf::TimePoint stamp, const lcmtf::Transform& value) {
  return lcmtf::TransformStamped{stamp, parent, child, value};
}

/// Stores parent_T_child and fails the test (with the buffer's reason) when it is refused.
inline void put(lcmtf::BufferCore& buffer, const std::string& parent, const std::string& child,
                lcmtf::TimePoint stamp, const lcmtf::Transform& value, bool is_static = false,
                const std::string& authority = "test") {
  std::string error;
  EXPECT_TRUE(
      buffer.setTransform(stamped(parent, child, stamp, value), authority, is_static, &error))
      << parent << " -> " << child << ": " << error;
}
inline void putStatic(lcmtf::BufferCore& buffer, const std::string& parent,
                      const std::string& child, const lcmtf::Transform& value,
                      const std::string& authority = "test") {
  put(buffer, parent, child, lcmtf::TimePoint{}, value, true, authority);
}

/// Translation within `tolerance` metres and every rotation-matrix entry within `tolerance`.
inline ::testing::AssertionResult near(const lcmtf::Transform& actual,
                                       const Eigen::Isometry3d& expected, double tolerance) {
  const double translation_error = (actual.translation - expected.translation()).norm();
  const double rotation_error =
      (actual.rotation.toRotationMatrix() - expected.linear()).cwiseAbs().maxCoeff();
  if (translation_error <= tolerance && rotation_error <= tolerance) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "translation " << actual.translation.transpose() << " vs expected "
         << expected.translation().transpose() << " (error " << translation_error
         << "), rotation matrix error " << rotation_error << ", tolerance " << tolerance;
}
inline ::testing::AssertionResult near(const lcmtf::Transform& actual,
                                       const lcmtf::Transform& expected, double tolerance) {
  Eigen::Isometry3d expected_isometry = Eigen::Isometry3d::Identity();
  expected_isometry.linear() = expected.rotation.normalized().toRotationMatrix();
  expected_isometry.translation() = expected.translation;
  return near(actual, expected_isometry, tolerance);
}

/// Bit-for-bit equality of translation and quaternion coefficients.
inline ::testing::AssertionResult identical(const lcmtf::Transform& actual,
                                            const lcmtf::Transform& expected) {
  if (actual.translation == expected.translation &&
      actual.rotation.coeffs() == expected.rotation.coeffs()) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "translation " << actual.translation.transpose() << " vs "
                                       << expected.translation.transpose() << ", rotation (xyzw) "
                                       << actual.rotation.coeffs().transpose() << " vs "
                                       << expected.rotation.coeffs().transpose();
}

}  // namespace lcmtf_test
