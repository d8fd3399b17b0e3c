#pragma once

#include <string>

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
/// fromMessage into `out`, in the room its strings already have (a receive loop reusing one).
void fromMessage(const transform_t& transform, TransformStamped& out);

/// parent_T_child as an Eigen isometry, from either form.
Eigen::Isometry3d toIsometry(const TransformStamped& transform);
Eigen::Isometry3d toIsometry(const transform_t& transform);
/// An isometry parent_T_child with its frames and stamp, in either form.
TransformStamped toTransformStamped(const Eigen::Isometry3d& parent_T_child, TimePoint stamp,
                                    std::string parent_frame, std::string child_frame);
transform_t toMessage(const Eigen::Isometry3d& parent_T_child, TimePoint stamp,
                      std::string parent_frame, std::string child_frame);

}  // namespace lcmtf
