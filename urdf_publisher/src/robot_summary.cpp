#include "lcmtf_urdf/robot_summary.hpp"

#include "lcmtf/programs/number_text.hpp"

namespace lcmtf::urdf {

using programs::formatNumber;

namespace {

std::string movableJointLine(const MovableJoint& joint, const std::string& prefix) {
  std::string line = "  " + std::string(toString(joint.motion)) + " " + joint.name + ": " + prefix +
                     joint.parent_link + " -> " + prefix + joint.child_link + ", axis [" +
                     formatNumber(joint.axis.x()) + " " + formatNumber(joint.axis.y()) + " " +
                     formatNumber(joint.axis.z()) + "]";
  if (joint.limits) {
    line += ", limits [" + formatNumber(joint.limits->lower) + ", " +
            formatNumber(joint.limits->upper) + "]";
  }
  if (joint.resolved_mimic) {
    const Mimic& mimic = *joint.resolved_mimic;
    line += ", follows " + formatNumber(mimic.multiplier) + " * " + mimic.leader + " + " +
            formatNumber(mimic.offset);
  }
  return line + "\n";
}

}  // namespace

std::string describeRobot(const RobotModel& robot, const std::string& frame_prefix,
                          bool list_joints) {
  std::size_t mimics = 0;
  for (const MovableJoint& joint : robot.movable_joints) mimics += joint.resolved_mimic ? 1 : 0;
  std::string text = "robot '" + robot.name + "' from " + robot.source + ": " +
                     std::to_string(robot.links.size()) + " links, root '" + frame_prefix +
                     robot.root_link + "'\n";
  text += "  joints set by joint states: " + std::to_string(robot.movable_joints.size() - mimics) +
          ", mimic joints following them: " + std::to_string(mimics) +
          ", fixed joints published once as static transforms: " +
          std::to_string(robot.fixed_joints.size()) + "\n";
  if (list_joints) {
    for (const MovableJoint& joint : robot.movable_joints)
      text += movableJointLine(joint, frame_prefix);
    for (const FixedJoint& joint : robot.fixed_joints) {
      text += "  fixed " + joint.name + ": " + frame_prefix + joint.parent_link + " -> " +
              frame_prefix + joint.child_link + "\n";
    }
  }
  for (const UnsupportedJoint& joint : robot.unsupported_joints) {
    const std::string parent = frame_prefix + joint.parent_link;
    const std::string child = frame_prefix + joint.child_link;
    text += "  " + joint.type + " joint '" + joint.name + "' (" + parent + " -> " + child +
            ") is not published: a joint state cannot carry its pose. Publish " + parent + "_T_" +
            child + " on TF yourself (a TransformBroadcaster, parent '" + parent + "', child '" +
            child + "')\n";
  }
  return text;
}

}  // namespace lcmtf::urdf
