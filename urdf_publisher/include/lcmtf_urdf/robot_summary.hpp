#pragma once

#include <string>

#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// What will be published for `robot`, why floating and planar joints are not and how to publish
/// them instead; `list_joints` adds a line per joint (type, frames, axis, limits, mimic).
std::string describeRobot(const RobotModel& robot, const std::string& frame_prefix,
                          bool list_joints = false);

}  // namespace lcmtf::urdf
