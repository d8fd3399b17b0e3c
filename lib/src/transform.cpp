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

namespace {
// The angle between two unit quaternions as 4-vectors, half the rotation angle between them.
// 2*atan2(|a-b|, |a+b|) stays accurate for tiny angles, where acos(a.b) does not.
double arcAngle(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  return 2.0 * std::atan2((a - b).norm(), (a + b).norm());
}
}  // namespace

double angularDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Vector4d bc =
      a.coeffs().dot(b.coeffs()) < 0.0 ? Eigen::Vector4d(-b.coeffs()) : b.coeffs();
  return 2.0 * arcAngle(a.coeffs(), bc);
}

Eigen::Quaterniond slerp(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double ratio) {
  if (ratio == 0.0) return a;
  Eigen::Vector4d bc = b.coeffs();
  if (a.coeffs().dot(bc) < 0.0) bc = -bc;
  if (ratio == 1.0) return Eigen::Quaterniond(bc);

  const double arc = arcAngle(a.coeffs(), bc);
  double weight_a = 1.0 - ratio;
  double weight_b = ratio;
  if (arc > 1e-9) {
    const double inverse_sine = 1.0 / std::sin(arc);
    weight_a = std::sin(weight_a * arc) * inverse_sine;
    weight_b = std::sin(weight_b * arc) * inverse_sine;
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
