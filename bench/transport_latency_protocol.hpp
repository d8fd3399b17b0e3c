// What the two processes of transport_latency_bench share: the frame tree, the channels, the
// clock, and the line protocol the sender uses to drive the receiver over its stdin/stdout.
#pragma once

#include <time.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace bench {

inline constexpr const char* kRawChannel = "TF_RAW_HOP";
inline constexpr const char* kRootFrame = "map";
inline constexpr const char* kDeepestFrame = "r_gripper_r_finger_tip_link";

struct Edge {
  std::string parent;
  std::string child;
};

// A PR2-like mobile manipulator: 60 dynamic edges, parents before children, the path from
// kRootFrame to kDeepestFrame (14 edges) finished by the last edge of the batch.
inline std::vector<Edge> robotEdges() {
  std::vector<Edge> edges{{"map", "odom"},
                          {"odom", "base_footprint"},
                          {"base_footprint", "base_link"},
                          {"base_link", "base_laser_link"},
                          {"base_link", "torso_lift_link"},
                          {"torso_lift_link", "head_pan_link"},
                          {"head_pan_link", "head_tilt_link"},
                          {"head_tilt_link", "head_plate_frame"},
                          {"head_plate_frame", "narrow_stereo_link"},
                          {"narrow_stereo_link", "narrow_stereo_optical_frame"},
                          {"head_plate_frame", "wide_stereo_link"},
                          {"wide_stereo_link", "wide_stereo_optical_frame"},
                          {"head_plate_frame", "head_mount_kinect_link"},
                          {"head_mount_kinect_link", "head_mount_kinect_rgb_optical_frame"},
                          {"torso_lift_link", "laser_tilt_mount_link"},
                          {"laser_tilt_mount_link", "laser_tilt_link"}};
  for (const char* caster : {"fl", "fr", "bl", "br"}) {
    const std::string name = std::string(caster) + "_caster_";
    edges.push_back({"base_link", name + "rotation_link"});
    edges.push_back({name + "rotation_link", name + "l_wheel_link"});
  }
  for (const std::string side : {"l", "r"}) {
    const auto link = [&side](const char* name) { return side + "_" + name; };
    const std::vector<std::pair<const char*, const char*>> arm{
        {nullptr, "shoulder_pan_link"},
        {"shoulder_pan_link", "shoulder_lift_link"},
        {"shoulder_lift_link", "upper_arm_roll_link"},
        {"upper_arm_roll_link", "upper_arm_link"},
        {"upper_arm_roll_link", "elbow_flex_link"},
        {"elbow_flex_link", "forearm_roll_link"},
        {"forearm_roll_link", "forearm_cam_frame"},
        {"forearm_cam_frame", "forearm_cam_optical_frame"},
        {"forearm_roll_link", "wrist_flex_link"},
        {"wrist_flex_link", "wrist_roll_link"},
        {"wrist_roll_link", "gripper_palm_link"},
        {"gripper_palm_link", "gripper_tool_frame"},
        {"gripper_palm_link", "gripper_motor_slider_link"},
        {"gripper_motor_slider_link", "gripper_motor_screw_link"},
        {"gripper_palm_link", "gripper_l_finger_link"},
        {"gripper_l_finger_link", "gripper_l_finger_tip_link"},
        {"gripper_palm_link", "gripper_r_finger_link"},
        {"gripper_r_finger_link", "gripper_r_finger_tip_link"}};
    for (const auto& [parent, child] : arm) {
      edges.push_back({parent ? link(parent) : "torso_lift_link", link(child)});
    }
  }
  return edges;
}

// Both processes read CLOCK_REALTIME (std::chrono::system_clock) on the same machine, so
// their microseconds compare directly; lcmtf stamps are on that clock too.
inline std::int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

inline std::int64_t processCpuNanos() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return std::int64_t{t.tv_sec} * 1000000000 + t.tv_nsec;
}

// One phase: batch k carries stamp base_us + k * period_us on every transform. The figures
// (and the receiver's CPU time) cover the batches from `measured_from` on; those before it
// warm up, and in the TF phase let the buffer fill its history.
struct Phase {
  enum class Kind { kRaw, kTf } kind = Kind::kRaw;
  std::int64_t base_us = 0;
  std::int64_t period_us = 1000;
  int count = 0;
  int measured_from = 0;

  std::int64_t stamp(int k) const { return base_us + k * period_us; }
  int index(std::int64_t stamp) const {
    const std::int64_t offset = stamp - base_us;
    if (offset < 0 || offset % period_us != 0 || offset / period_us >= count) return -1;
    return static_cast<int>(offset / period_us);
  }

  std::string format() const {
    return std::string(kind == Kind::kRaw ? "RAW" : "TF") + " " + std::to_string(base_us) + " " +
           std::to_string(period_us) + " " + std::to_string(count) + " " +
           std::to_string(measured_from);
  }
  static bool parse(const std::string& line, Phase& phase) {
    char kind[8] = {};
    long long base = 0;
    long long period = 0;
    if (std::sscanf(line.c_str(), "%7s %lld %lld %d %d", kind, &base, &period, &phase.count,
                    &phase.measured_from) != 5 ||
        period <= 0 || phase.count <= phase.measured_from || phase.measured_from < 0) {
      return false;
    }
    phase.kind = std::string(kind) == "TF" ? Kind::kTf : Kind::kRaw;
    phase.base_us = base;
    phase.period_us = period;
    return std::string(kind) == "TF" || std::string(kind) == "RAW";
  }
};

// The receiver's answer after "END": a line
//   RESULT <received> <late> <lookup_errors> <cpu_ns> <wall_us>
// then one "<k> <done_us>" line per batch seen, then "DONE". cpu_ns and wall_us span the
// measured batches, from the first seen to the last seen; 0 when there were none.
struct Outcome {
  std::int64_t received = 0;
  std::int64_t late = 0;
  std::int64_t lookup_errors = 0;
  std::int64_t cpu_ns = 0;
  std::int64_t wall_us = 0;
  std::vector<std::int64_t> done_us;
};

int runReceiver(const std::string& url);

}  // namespace bench
