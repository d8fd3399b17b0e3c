#include "lcmtf/do_transform.hpp"

#include <stdexcept>
#include <string>

namespace lcmtf {

// Every form below rotates through the same 3x3 matrix, so each coordinate of a result is a
// sum of products: infinite and NaN inputs come out the same whichever form carries them.

Eigen::Vector3d transformed(const Transform& target_T_source, const Eigen::Vector3d& point) {
  return target_T_source * point;
}

Direction transformed(const Transform& target_T_source, const Direction& direction) {
  return Direction{target_T_source.rotate(direction.value)};
}

Eigen::Quaterniond transformed(const Transform& target_T_source,
                               const Eigen::Quaterniond& rotation) {
  return target_T_source.rotation * rotation;
}

Transform transformed(const Transform& target_T_source, const Transform& pose) {
  return Transform(target_T_source * pose.translation, target_T_source.rotation * pose.rotation);
}

Eigen::Isometry3d transformed(const Transform& target_T_source, const Eigen::Isometry3d& pose) {
  return target_T_source.toIsometry() * pose;
}

Eigen::Matrix3Xd transformed(const Transform& target_T_source, const Eigen::Matrix3Xd& cloud) {
  Eigen::Matrix3Xd result(3, cloud.cols());
  transformCloud(target_T_source, cloud, result);
  return result;
}

void transformCloud(const Transform& target_T_source,
                    const Eigen::Ref<const Eigen::Matrix3Xd>& cloud,
                    Eigen::Ref<Eigen::Matrix3Xd> result) {
  if (result.cols() != cloud.cols()) {
    throw std::invalid_argument("transformCloud: " + std::to_string(cloud.cols()) +
                                " points into room for " + std::to_string(result.cols()));
  }
  // One pass over the points, rotation as a matrix: memory, not arithmetic, bounds this.
  const Eigen::Matrix3d rotation = target_T_source.rotationMatrix();
  const Eigen::Vector3d translation = target_T_source.translation;
  for (Eigen::Index i = 0; i < cloud.cols(); ++i) {
    result.col(i) = rotation * cloud.col(i) + translation;
  }
}

std::vector<Eigen::Vector3d> transformed(const Transform& target_T_source,
                                         const std::vector<Eigen::Vector3d>& cloud) {
  const Eigen::Matrix3d rotation = target_T_source.rotationMatrix();
  const Eigen::Vector3d translation = target_T_source.translation;
  std::vector<Eigen::Vector3d> result(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) result[i] = rotation * cloud[i] + translation;
  return result;
}

Twist transformed(const Transform& target_T_source, const Twist& twist) {
  const Eigen::Matrix3d rotation = target_T_source.rotationMatrix();
  const Eigen::Vector3d angular = rotation * twist.angular;
  return Twist{rotation * twist.linear + target_T_source.translation.cross(angular), angular};
}

Wrench transformed(const Transform& target_T_source, const Wrench& wrench) {
  const Eigen::Matrix3d rotation = target_T_source.rotationMatrix();
  const Eigen::Vector3d force = rotation * wrench.force;
  return Wrench{force, rotation * wrench.torque + target_T_source.translation.cross(force)};
}

PoseWithCovariance transformed(const Transform& target_T_source, const PoseWithCovariance& pose) {
  // J S J^T with J = diag(R, R), block by block: J's zero blocks never multiply S, so an
  // infinite variance in one block cannot turn the other blocks into NaN.
  const Eigen::Matrix3d rotation = target_T_source.rotationMatrix();
  const Eigen::Matrix3d rotation_transposed = rotation.transpose();
  Eigen::Matrix<double, 6, 6> covariance;
  for (int row = 0; row < 6; row += 3) {
    for (int col = 0; col < 6; col += 3) {
      const Eigen::Matrix3d rotated_rows = rotation * pose.covariance.block<3, 3>(row, col);
      covariance.block<3, 3>(row, col) = rotated_rows * rotation_transposed;
    }
  }
  return PoseWithCovariance{transformed(target_T_source, pose.pose), covariance};
}

}  // namespace lcmtf
