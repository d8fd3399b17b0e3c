#include "demo_report.hpp"

#include <cstdio>

#include "lcmtf/programs/roll_pitch_yaw.hpp"

namespace lcmtf::demo {

namespace {

std::string vector(const Eigen::Vector3d& v) {
  char text[64];
  std::snprintf(text, sizeof text, "[%6.3f %6.3f %6.3f]", v.x(), v.y(), v.z());
  return text;
}

}  // namespace

std::optional<DemoReport> makeDemoReport(const BufferCore& buffer, const DemoFrames& frames,
                                         Duration look_back,
                                         const Eigen::Vector3d& object_in_camera,
                                         std::string* why) {
  try {
    DemoReport report;
    report.time = std::min(buffer.getLatestCommonTime(frames.fixed, frames.end_effector),
                           buffer.getLatestCommonTime(frames.fixed, frames.camera));
    report.seen_at = report.time - look_back;
    if (!buffer.canTransform(frames.fixed, frames.camera, report.seen_at, why)) {
      return std::nullopt;
    }
    report.base_T_end_effector =
        buffer.lookupTransform(frames.base, frames.end_effector, report.time).transform;
    report.object_in_camera = object_in_camera;
    report.object_in_fixed =
        buffer.lookupTransform(frames.fixed, frames.camera, report.seen_at).transform *
        object_in_camera;
    report.object_in_base =
        buffer
            .lookupTransform(frames.base, report.time, frames.camera, report.seen_at, frames.fixed)
            .transform *
        object_in_camera;
    return report;
  } catch (const TransformException& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
}

std::string formatDemoReport(const DemoReport& report, const DemoFrames& frames) {
  const programs::RollPitchYaw angles =
      programs::toRollPitchYaw(report.base_T_end_effector.rotation);
  const Eigen::Vector3d rpy(angles.roll, angles.pitch, angles.yaw);
  char age[32];
  std::snprintf(age, sizeof age, "%.1f s", toSeconds(report.time - report.seen_at));
  return "t=" + toString(report.time) + "  " + frames.end_effector + " in " + frames.base +
         ": xyz " + vector(report.base_T_end_effector.translation) + "  rpy " + vector(rpy) +
         "\n    what the camera saw " + age + " ago at " + vector(report.object_in_camera) +
         " in " + frames.camera + " is now at " + vector(report.object_in_base) + " in " +
         frames.base + " (" + vector(report.object_in_fixed) + " in " + frames.fixed + ")";
}

}  // namespace lcmtf::demo
