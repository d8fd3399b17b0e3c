#pragma once

#include <cmath>

#include "lcmtf/transform.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// parent_T_child of `joint` at `position` (radians, or metres for a prismatic joint): the
/// origin, then a turn about the axis or a slide along it.
inline Transform parentTChild(const MovableJoint& joint, double position) {
  const Transform& origin = joint.parent_T_origin;
  if (joint.motion == JointMotion::kPrismatic) {
    return Transform(origin.translation + origin.rotation * (joint.axis * position),
                     origin.rotation);
  }
  const double half = 0.5 * position;
  const double sin_half = std::sin(half);
  const Eigen::Quaterniond turn(std::cos(half), sin_half * joint.axis.x(),
                                sin_half * joint.axis.y(), sin_half * joint.axis.z());
  return Transform(origin.translation, origin.rotation * turn);
}

/// The position of a mimic joint whose resolved leader is at `leader_position`.
inline double mimicPosition(const Mimic& resolved, double leader_position) {
  return resolved.multiplier * leader_position + resolved.offset;
}

}  // namespace lcmtf::urdf
