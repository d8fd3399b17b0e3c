#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "lcmtf/time.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf_test {

/// odom_T_base of the transport peer at `stamp`: translation linear in time and rotation at a
/// constant rate about a fixed axis, so lerp and slerp between any two samples reproduce it
/// exactly. `origin` is where the motion starts; `speed` scales it (a restarted peer uses another).
inline lcmtf::Transform odomTBase(lcmtf::TimePoint stamp, lcmtf::TimePoint origin, double speed) {
  const double s = lcmtf::toSeconds(stamp - origin);
  const Eigen::Vector3d start(1.0, 2.0, 0.3);
  const Eigen::Vector3d velocity(0.5, -0.25, 0.1);
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  return lcmtf::Transform(start + speed * s * velocity,
                          Eigen::Quaterniond(Eigen::AngleAxisd(0.8 * speed * s, axis)));
}

/// The static tree of the transport peer: base -> camera -> camera_optical, base -> lidar.
inline std::vector<lcmtf::TransformStamped> peerStatics() {
  const auto rotation = [](double angle, const Eigen::Vector3d& axis) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
  };
  return {
      {lcmtf::kLatestTime, "base", "camera",
       lcmtf::Transform({0.2, 0.0, 0.5}, rotation(0.3, Eigen::Vector3d::UnitY()))},
      {lcmtf::kLatestTime, "camera", "camera_optical",
       lcmtf::Transform({0.0, 0.0, 0.0}, rotation(-1.5707963267948966, Eigen::Vector3d::UnitZ()))},
      {lcmtf::kLatestTime, "base", "lidar",
       lcmtf::Transform({-0.1, 0.0, 0.8}, rotation(1.0, Eigen::Vector3d::UnitZ()))},
  };
}

}  // namespace lcmtf_test
