#pragma once

#include <string>

#include <Eigen/Core>

#include "lcmtf/time.hpp"

namespace lcmtf {

/// Linear (m/s) and angular (rad/s) velocity of one frame relative to another, expressed in
/// `frame`, averaged over an interval centred on `stamp`.
struct Velocity {
  TimePoint stamp;
  std::string frame;
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();
};

}  // namespace lcmtf
