#pragma once

#include <string>

#include "lcmtf/time.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf::nodes {

/// The pose of the child frame in the parent frame as lcmtf-echo prints it: stamp and age
/// at `now`, translation, quaternion, roll/pitch/yaw in radians and degrees, 4x4 matrix.
std::string formatPose(const TransformStamped& parent_T_child, TimePoint now, int precision);

/// `value` with `precision` decimals, and no minus sign on a value that rounds to zero.
std::string fixedDecimals(double value, int precision);

}  // namespace lcmtf::nodes
