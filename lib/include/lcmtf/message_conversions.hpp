#pragma once

#include <Eigen/Geometry>

#include "lcmtf/quaternion_t.hpp"
#include "lcmtf/transform_stamped.hpp"
#include "lcmtf/transform_t.hpp"
#include "lcmtf/vector3_t.hpp"

namespace lcmtf {

/// Between the LCM wire types and the math types; values are copied as they are, unchecked.
vector3_t toMessage(const Eigen::Vector3d& vector);
quaternion_t toMessage(const Eigen::Quaterniond& rotation);
transform_t toMessage(const TransformStamped& transform);

Eigen::Vector3d fromMessage(const vector3_t& vector);
Eigen::Quaterniond fromMessage(const quaternion_t& rotation);
TransformStamped fromMessage(const transform_t& transform);

}  // namespace lcmtf
