#pragma once

#include "lcmtf/transform.hpp"

namespace lcmtf::detail {

/// q v q*, written out so that it inlines into hot loops (Eigen's own call does not).
inline Eigen::Vector3d rotated(const Eigen::Quaterniond& q, const Eigen::Vector3d& v) {
  const Eigen::Vector3d twice_cross = 2.0 * q.vec().cross(v);
  return v + q.w() * twice_cross + q.vec().cross(twice_cross);
}

/// above * below.
inline Transform composed(const Transform& above, const Transform& below) {
  return Transform(rotated(above.rotation, below.translation) + above.translation,
                   above.rotation * below.rotation);
}

}  // namespace lcmtf::detail
