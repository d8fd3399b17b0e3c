#include "lcmtf/programs/roll_pitch_yaw.hpp"

#include <cmath>

namespace lcmtf::programs {

namespace {

// Below this cos(pitch) the roll and yaw axes coincide to within rounding.
constexpr double kGimbalLockCosine = 1e-9;

}  // namespace

Eigen::Quaterniond toQuaternion(const RollPitchYaw& angles) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angles.yaw, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(angles.pitch, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(angles.roll, Eigen::Vector3d::UnitX()))
      .normalized();
}

RollPitchYaw toRollPitchYaw(const Eigen::Quaterniond& rotation) {
  const Eigen::Matrix3d m = rotation.normalized().toRotationMatrix();
  RollPitchYaw angles;
  const double cos_pitch = std::hypot(m(0, 0), m(1, 0));
  angles.pitch = std::atan2(-m(2, 0), cos_pitch);
  if (cos_pitch > kGimbalLockCosine) {
    angles.roll = std::atan2(m(2, 1), m(2, 2));
    angles.yaw = std::atan2(m(1, 0), m(0, 0));
  } else if (m(2, 0) < 0.0) {  // pitch +pi/2: m(0,1) = sin(roll - yaw), m(1,1) = cos(roll - yaw)
    angles.roll = std::atan2(m(0, 1), m(1, 1));
  } else {  // pitch -pi/2: m(0,1) = -sin(roll + yaw), m(1,1) = cos(roll + yaw)
    angles.roll = std::atan2(-m(0, 1), m(1, 1));
  }
  return angles;
}

}  // namespace lcmtf::programs
