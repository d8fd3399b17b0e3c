#pragma once

#include <Eigen/Core>

#include "lcmtf/transform.hpp"

namespace lcmtf {

/// A free vector (a direction, a velocity, a force): transforming it only rotates it.
/// A bare Eigen::Vector3d is a point and is also translated.
struct Direction {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

/// A rigid body's velocity: `linear` is that of the body point at the frame's origin, both
/// vectors expressed in the frame (m/s, rad/s).
struct Twist {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();
};

/// A force and the torque about the frame's origin, expressed in the frame (N, N m).
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

/// A pose with the covariance of its error, ordered (x, y, z, rotation about x, y, z) and
/// expressed in the axes of the frame the pose is given in, as ROS messages have it.
struct PoseWithCovariance {
  Transform pose;
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
};

}  // namespace lcmtf
