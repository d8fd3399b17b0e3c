#include "lcmtf/transform.hpp"

#include <algorithm>
#include <cmath>

namespace lcmtf {

Eigen::Isometry3d Transform::toIsometry() const {
  Eigen::Isometry3d isometry = Eigen::Isometry3d::Identity();
  isometry.linear() = rotation.toRotationMatrix();
  isometry.translation() = translation;
  return isometry;
}

Transform Transform::fromIsometry(const Eigen::Isometry3d& isometry) {
  return Transform(isometry.translation(),
                   Eigen::Quaterniond(Eigen::Matrix3d(isometry.linear())).normalized());
}

bool Transform::isApprox(const Transform& other, double tolerance) const {
  return (translation - other.translation).norm() <= tolerance &&
         angularDistance(rotation, other.rotation) <= tolerance;
}

double angularDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  // 2*atan2(|a-b|, |a+b|) stays accurate for tiny angles, where acos(dot) does not.
  Eigen::Vector4d bc = b.coeffs();
  if (a.coeffs().dot(bc) < 0.0) bc = -bc;
  return 2.0 * std::atan2((a.coeffs() - bc).norm(), (a.coeffs() + bc).norm());
}

Eigen::Quaterniond slerp(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b,
                         double ratio) {
  if (ratio == 0.0) return a;
  Eigen::Vector4d bc = b.coeffs();
  if (a.coeffs().dot(bc) < 0.0) bc = -bc;
  if (ratio == 1.0) return Eigen::Quaterniond(bc);

  const double half_angle = 0.5 * angularDistance(a, Eigen::Quaterniond(bc));
  double weight_a = 1.0 - ratio;
  double weight_b = ratio;
  if (half_angle > 1e-9) {
    const double inverse_sine = 1.0 / std::sin(half_angle);
    weight_a = std::sin(weight_a * half_angle) * inverse_sine;
    weight_b = std::sin(weight_b * half_angle) * inverse_sine;
  }
  Eigen::Quaterniond result(weight_a * a.coeffs() + weight_b * bc);
  result.normalize();
  return result;
}

Transform interpolate(const Transform& a, const Transform& b, double ratio) {
  if (ratio == 0.0) return a;
  if (ratio == 1.0) return b;
  return Transform(a.translation + ratio * (b.translation - a.translation),
                   slerp(a.rotation, b.rotation, ratio));
}

}  // namespace lcmtf
