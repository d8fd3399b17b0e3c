#pragma once

#include <Eigen/Geometry>

namespace lcmtf::programs {

/// Angles in radians of the rotation Rz(yaw) * Ry(pitch) * Rx(roll): roll about x first, then
/// pitch about the fixed y, then yaw about the fixed z (the ROS and URDF convention).
struct RollPitchYaw {
  double roll = 0.0;
  double pitch = 0.0;
  double yaw = 0.0;
};

/// The unit quaternion of `angles`.
Eigen::Quaterniond toQuaternion(const RollPitchYaw& angles);

/// The angles of `rotation` with pitch in [-pi/2, pi/2] and roll, yaw in [-pi, pi]; at pitch
/// +-pi/2 (gimbal lock) yaw is 0 and roll carries the whole remaining turn.
RollPitchYaw toRollPitchYaw(const Eigen::Quaterniond& rotation);

}  // namespace lcmtf::programs
