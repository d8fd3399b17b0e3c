#pragma once

#include <string>

#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// Lines saying what will be published for `robot` (frames named with `frame_prefix`), and
/// for each floating or planar joint that it is not, and how to publish it instead.
/// `list_joints` adds one line per joint with its type, frames, axis and limits.
std::string describeRobot(const RobotModel& robot, const std::string& frame_prefix,
                          bool list_joints = false);

}  // namespace lcmtf::urdf
