#pragma once

#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "lcmtf/buffer_core.hpp"

namespace lcmtf::demo {

/// The frames the demo asks about; the defaults are those of examples/mobile_manipulator.urdf.
struct DemoFrames {
  std::string base = "base_link";
  std::string end_effector = "gripper_tcp";
  std::string camera = "camera_optical_frame";
  std::string fixed = "odom";  ///< a frame that does not move while the robot does
};

/// What the demo prints each time: the end effector now, and where an object the camera saw
/// `look_back` ago is now, found by time travel through the fixed frame.
struct DemoReport {
  TimePoint time;                    ///< the latest time every frame involved has data
  Transform base_T_end_effector;     ///< at `time`
  TimePoint seen_at;                 ///< when the camera saw the object
  Eigen::Vector3d object_in_camera;  ///< where the camera saw it, at `seen_at`
  Eigen::Vector3d object_in_fixed;   ///< the same point in the fixed frame
  Eigen::Vector3d object_in_base;    ///< the same point in the base frame at `time`
};

/// The report for the latest data in `buffer`, or nothing (and in `why`, what is missing)
/// while the buffer holds less than `look_back` of history or lacks a frame.
std::optional<DemoReport> makeDemoReport(const BufferCore& buffer, const DemoFrames& frames,
                                         Duration look_back,
                                         const Eigen::Vector3d& object_in_camera,
                                         std::string* why = nullptr);

/// The report as two lines of text (no newline at the end).
std::string formatDemoReport(const DemoReport& report, const DemoFrames& frames);

}  // namespace lcmtf::demo
