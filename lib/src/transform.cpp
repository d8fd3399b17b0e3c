#include "lcmtf/transform.hpp"

#include <algorithm>
#include <cmath>

#include "slerp_weights.hpp"

namespace lcmtf {

Eigen::Matrix3d Transform::rotationMatrix() const {
  const double x = rotation.x();
  const double y = rotation.y();
  const double z = rotation.z();
  const double w = rotation.w();
  const double scale = 2.0 / (x * x + y * y + z * z + w * w);
  const double xs = x * scale;
  const double ys = y * scale;
  const double zs = z * scale;
  const double xx = x * xs, xy = x * ys, xz = x * zs;
  const double yy = y * ys, yz = y * zs, zz = z * zs;
  const double wx = w * xs, wy = w * ys, wz = w * zs;
  Eigen::Matrix3d matrix;
  matrix << 1.0 - (yy + zz), xy - wz, xz + wy,  //
      xy + wz, 1.0 - (xx + zz), yz - wx,        //
      xz - wy, yz + wx, 1.0 - (xx + yy);
  return matrix;
}

Eigen::Isometry3d Transform::toIsometry() const {
  Eigen::Isometry3d isometry = Eigen::Isometry3d::Identity();
  isometry.linear() = rotationMatrix();
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

  double weight_a = 1.0 - ratio;
  double weight_b = ratio;
  detail::slerpWeights(0.25 * (a.coeffs() - bc).squaredNorm(), weight_a, weight_b);
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
