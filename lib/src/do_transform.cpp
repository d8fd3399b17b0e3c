#include "lcmtf/do_transform.hpp"

namespace lcmtf {

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
  return target_T_source * pose;
}

Eigen::Isometry3d transformed(const Transform& target_T_source, const Eigen::Isometry3d& pose) {
  return target_T_source.toIsometry() * pose;
}

Eigen::Matrix3Xd transformed(const Transform& target_T_source, const Eigen::Matrix3Xd& cloud) {
  // One pass over the points, rotation as a matrix: memory, not arithmetic, bounds this.
  const Eigen::Matrix3d rotation = target_T_source.rotation.toRotationMatrix();
  const Eigen::Vector3d translation = target_T_source.translation;
  Eigen::Matrix3Xd result(3, cloud.cols());
  for (Eigen::Index i = 0; i < cloud.cols(); ++i) {
    result.col(i) = rotation * cloud.col(i) + translation;
  }
  return result;
}

std::vector<Eigen::Vector3d> transformed(const Transform& target_T_source,
                                         const std::vector<Eigen::Vector3d>& cloud) {
  const Eigen::Matrix3d rotation = target_T_source.rotation.toRotationMatrix();
  const Eigen::Vector3d translation = target_T_source.translation;
  std::vector<Eigen::Vector3d> result(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) result[i] = rotation * cloud[i] + translation;
  return result;
}

Twist transformed(const Transform& target_T_source, const Twist& twist) {
  const Eigen::Vector3d angular = target_T_source.rotate(twist.angular);
  return Twist{target_T_source.rotate(twist.linear) + target_T_source.translation.cross(angular),
               angular};
}

Wrench transformed(const Transform& target_T_source, const Wrench& wrench) {
  const Eigen::Vector3d force = target_T_source.rotate(wrench.force);
  return Wrench{force,
                target_T_source.rotate(wrench.torque) + target_T_source.translation.cross(force)};
}

PoseWithCovariance transformed(const Transform& target_T_source, const PoseWithCovariance& pose) {
  const Eigen::Matrix3d rotation = target_T_source.rotation.toRotationMatrix();
  Eigen::Matrix<double, 6, 6> jacobian = Eigen::Matrix<double, 6, 6>::Zero();
  jacobian.topLeftCorner<3, 3>() = rotation;
  jacobian.bottomRightCorner<3, 3>() = rotation;
  return PoseWithCovariance{target_T_source * pose.pose,
                            jacobian * pose.covariance * jacobian.transpose()};
}

}  // namespace lcmtf
