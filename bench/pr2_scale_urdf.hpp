#pragma once

// A URDF the size and shape of the PR2's: an omnidirectional base on four casters, a lifting
// torso, a pan-tilt head full of cameras, two seven-joint arms with forearm cameras, and
// grippers whose fingers follow one joint through mimic chains. Made up, not the PR2's
// numbers: only its scale matters here.

#include <string>
#include <vector>

namespace bench {

class UrdfWriter {
 public:
  explicit UrdfWriter(const std::string& robot) { text_ = "<robot name=\"" + robot + "\">\n"; }

  void link(const std::string& name) { text_ += "  <link name=\"" + name + "\"/>\n"; }

  // A joint to a new link `child`; `type` as URDF spells it; `limits` "lower upper" or "".
  void joint(const std::string& name, const std::string& type, const std::string& parent,
             const std::string& child, const std::string& xyz, const std::string& rpy = "0 0 0",
             const std::string& axis = "0 0 1", const std::string& limits = "",
             const std::string& mimic = "") {
    link(child);
    text_ += "  <joint name=\"" + name + "\" type=\"" + type + "\">\n    <parent link=\"" + parent +
             "\"/>\n    <child link=\"" + child + "\"/>\n    <origin xyz=\"" + xyz + "\" rpy=\"" +
             rpy + "\"/>\n";
    if (type != "fixed") text_ += "    <axis xyz=\"" + axis + "\"/>\n";
    if (!limits.empty()) {
      const auto space = limits.find(' ');
      text_ += "    <limit lower=\"" + limits.substr(0, space) + "\" upper=\"" +
               limits.substr(space + 1) + "\" effort=\"30\" velocity=\"2\"/>\n";
    }
    if (!mimic.empty()) text_ += "    <mimic joint=\"" + mimic + "\" multiplier=\"1\"/>\n";
    text_ += "  </joint>\n";
  }

  std::string finish() { return text_ + "</robot>\n"; }

 private:
  std::string text_;
};

inline void addCamera(UrdfWriter& urdf, const std::string& parent, const std::string& name,
                      const std::string& xyz) {
  urdf.joint(name + "_frame_joint", "fixed", parent, name + "_frame", xyz);
  urdf.joint(name + "_optical_frame_joint", "fixed", name + "_frame", name + "_optical_frame",
             "0 0 0", "-1.5707963267948966 0 -1.5707963267948966");
}

inline void addArm(UrdfWriter& urdf, const std::string& side) {
  const std::string s = side + "_";
  const std::string y = side == "l" ? "0.188" : "-0.188";
  urdf.joint(s + "shoulder_pan_joint", "revolute", "torso_lift_link", s + "shoulder_pan_link",
             "0 " + y + " 0", "0 0 0", "0 0 1", "-2.1 2.1");
  urdf.joint(s + "shoulder_lift_joint", "revolute", s + "shoulder_pan_link",
             s + "shoulder_lift_link", "0.1 0 0", "0 0 0", "0 1 0", "-0.5 1.3");
  urdf.joint(s + "upper_arm_roll_joint", "revolute", s + "shoulder_lift_link",
             s + "upper_arm_roll_link", "0 0 0", "0 0 0", "1 0 0", "-3.7 0.8");
  urdf.joint(s + "upper_arm_joint", "fixed", s + "upper_arm_roll_link", s + "upper_arm_link",
             "0 0 0");
  urdf.joint(s + "elbow_flex_joint", "revolute", s + "upper_arm_link", s + "elbow_flex_link",
             "0.4 0 0", "0 0 0", "0 1 0", "-2.3 0");
  urdf.joint(s + "forearm_roll_joint", "continuous", s + "elbow_flex_link", s + "forearm_roll_link",
             "0 0 0", "0 0 0", "1 0 0");
  urdf.joint(s + "forearm_joint", "fixed", s + "forearm_roll_link", s + "forearm_link", "0 0 0");
  addCamera(urdf, s + "forearm_roll_link", s + "forearm_cam", "0.135 0 0.044");
  urdf.joint(s + "wrist_flex_joint", "revolute", s + "forearm_link", s + "wrist_flex_link",
             "0.321 0 0", "0 0 0", "0 1 0", "-2.1 0");
  urdf.joint(s + "wrist_roll_joint", "continuous", s + "wrist_flex_link", s + "wrist_roll_link",
             "0 0 0", "0 0 0", "1 0 0");
  urdf.joint(s + "gripper_palm_joint", "fixed", s + "wrist_roll_link", s + "gripper_palm_link",
             "0 0 0");
  urdf.joint(s + "gripper_tool_joint", "fixed", s + "gripper_palm_link", s + "gripper_tool_frame",
             "0.18 0 0");
  urdf.joint(s + "gripper_led_joint", "fixed", s + "gripper_palm_link", s + "gripper_led_frame",
             "0.05 0 0.03");
  urdf.joint(s + "gripper_motor_slider_joint", "prismatic", s + "gripper_palm_link",
             s + "gripper_motor_slider_link", "0.17 0 0", "0 0 0", "1 0 0", "-0.1 0.1");
  urdf.joint(s + "gripper_motor_screw_joint", "continuous", s + "gripper_motor_slider_link",
             s + "gripper_motor_screw_link", "0 0 0", "0 0 0", "0 1 0");
  urdf.joint(s + "gripper_l_finger_joint", "revolute", s + "gripper_palm_link",
             s + "gripper_l_finger_link", "0.077 0.01 0", "0 0 0", "0 0 1", "0 0.55");
  urdf.joint(s + "gripper_r_finger_joint", "revolute", s + "gripper_palm_link",
             s + "gripper_r_finger_link", "0.077 -0.01 0", "0 0 0", "0 0 -1", "0 0.55",
             s + "gripper_l_finger_joint");
  urdf.joint(s + "gripper_l_finger_tip_joint", "revolute", s + "gripper_l_finger_link",
             s + "gripper_l_finger_tip_link", "0.091 0.005 0", "0 0 0", "0 0 -1", "0 0.55",
             s + "gripper_l_finger_joint");
  urdf.joint(s + "gripper_r_finger_tip_joint", "revolute", s + "gripper_r_finger_link",
             s + "gripper_r_finger_tip_link", "0.091 -0.005 0", "0 0 0", "0 0 1", "0 0.55",
             s + "gripper_r_finger_joint");
  urdf.joint(s + "gripper_joint", "prismatic", s + "gripper_r_finger_tip_link",
             s + "gripper_l_finger_tip_frame", "0 0 0", "0 0 0", "0 1 0", "0 0.09");
}

/// The PR2-scale robot's URDF text.
inline std::string pr2ScaleUrdf() {
  UrdfWriter urdf("pr2_scale");
  urdf.link("base_footprint");
  urdf.joint("base_footprint_joint", "fixed", "base_footprint", "base_link", "0 0 0.051");
  for (const char* corner : {"fl", "fr", "bl", "br"}) {
    const std::string c = corner;
    const std::string x = c[0] == 'f' ? "0.2246" : "-0.2246";
    const std::string y = c[1] == 'l' ? "0.2246" : "-0.2246";
    urdf.joint(c + "_caster_rotation_joint", "continuous", "base_link", c + "_caster_rotation_link",
               x + " " + y + " 0.0282");
    urdf.joint(c + "_caster_l_wheel_joint", "continuous", c + "_caster_rotation_link",
               c + "_caster_l_wheel_link", "0 0.049 0", "0 0 0", "0 1 0");
    urdf.joint(c + "_caster_r_wheel_joint", "continuous", c + "_caster_rotation_link",
               c + "_caster_r_wheel_link", "0 -0.049 0", "0 0 0", "0 1 0");
  }
  urdf.joint("base_laser_joint", "fixed", "base_link", "base_laser_link", "0.275 0 0.252");
  urdf.joint("base_bellow_joint", "fixed", "base_link", "base_bellow_link", "-0.29 0 0.8");
  urdf.joint("imu_joint", "fixed", "base_link", "imu_link", "-0.02977 -0.1497 0.164");
  urdf.joint("torso_lift_joint", "prismatic", "base_link", "torso_lift_link", "-0.05 0 0.739",
             "0 0 0", "0 0 1", "0 0.33");
  urdf.joint("torso_lift_motor_screw_joint", "continuous", "base_link",
             "torso_lift_motor_screw_link", "-0.15 0 0.7");
  urdf.joint("head_pan_joint", "revolute", "torso_lift_link", "head_pan_link", "-0.01707 0 0.38145",
             "0 0 0", "0 0 1", "-3.0 3.0");
  urdf.joint("head_tilt_joint", "revolute", "head_pan_link", "head_tilt_link", "0.068 0 0", "0 0 0",
             "0 1 0", "-0.47 1.39");
  urdf.joint("head_plate_frame_joint", "fixed", "head_tilt_link", "head_plate_frame",
             "0.0232 0 0.0645");
  urdf.joint("sensor_mount_joint", "fixed", "head_plate_frame", "sensor_mount_link", "0 0 0");
  const std::vector<std::pair<std::string, std::string>> cameras{
      {"narrow_stereo_l", "0.045 0.03 0.0305"}, {"narrow_stereo_r", "0.045 -0.06 0.0305"},
      {"wide_stereo_l", "0.045 0.06 0.0305"},   {"wide_stereo_r", "0.045 -0.03 0.0305"},
      {"high_def", "0.046 -0.11 0.0475"},       {"head_mount_kinect_rgb", "-0.01 0.0125 0.026"}};
  for (const auto& [name, xyz] : cameras) addCamera(urdf, "sensor_mount_link", name, xyz);
  urdf.joint("laser_tilt_mount_joint", "revolute", "torso_lift_link", "laser_tilt_mount_link",
             "0.09893 0 0.227", "0 0 0", "0 1 0", "-0.79 1.48");
  urdf.joint("laser_tilt_joint", "fixed", "laser_tilt_mount_link", "laser_tilt_link", "0 0 0.03");
  addArm(urdf, "l");
  addArm(urdf, "r");
  return urdf.finish();
}

}  // namespace bench
