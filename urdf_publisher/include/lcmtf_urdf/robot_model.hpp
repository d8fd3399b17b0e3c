#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lcmtf/transform.hpp"

namespace lcmtf::urdf {

/// A robot description that cannot be published; what() names where it came from and why.
class UrdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How a movable joint moves its child: turning about its axis, or sliding along it.
enum class JointMotion { kRevolute, kContinuous, kPrismatic };

/// "revolute", "continuous" or "prismatic", as URDF spells them.
const char* toString(JointMotion motion);

/// The range a joint's position may take (radians or metres).
struct PositionLimits {
  double lower = 0.0;
  double upper = 0.0;
};

/// A joint whose position follows another's: multiplier * leader + offset.
struct Mimic {
  std::string leader;
  double multiplier = 1.0;
  double offset = 0.0;
};

/// A joint that joint states drive: parent_T_child = parent_T_origin * motion(position).
struct MovableJoint {
  std::string name;
  std::string parent_link;
  std::string child_link;
  JointMotion motion = JointMotion::kRevolute;
  Transform parent_T_origin;                        ///< the URDF <origin>
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  ///< unit length, in the joint's frame
  std::optional<PositionLimits> limits;             ///< none for continuous joints
  std::optional<Mimic> mimic;                       ///< as the URDF writes it
  /// For a mimic joint, the same relation resolved through the whole chain, so `leader` is
  /// a joint that follows no other.
  std::optional<Mimic> resolved_mimic;
};

/// A joint that never moves, published once as a static transform.
struct FixedJoint {
  std::string name;
  std::string parent_link;
  std::string child_link;
  Transform parent_T_child;
};

/// A floating or planar joint: it needs a whole pose, which a joint state cannot carry.
struct UnsupportedJoint {
  std::string name;
  std::string type;  ///< "floating" or "planar"
  std::string parent_link;
  std::string child_link;
};

/// A robot as lcmtf publishes it: read from a URDF, checked, joints in tree order from the root.
struct RobotModel {
  std::string name;
  std::string source;  ///< the file it was read from, or the channel and sender
  std::string urdf;    ///< the URDF text itself
  std::string root_link;
  std::vector<std::string> links;
  std::vector<MovableJoint> movable_joints;
  std::vector<FixedJoint> fixed_joints;
  std::vector<UnsupportedJoint> unsupported_joints;

  /// The movable joint of that name, or null.
  const MovableJoint* findMovableJoint(const std::string& joint_name) const;
};

/// Reads and checks the URDF file at `path`; throws UrdfError naming the file and the problem.
RobotModel loadRobotModel(const std::string& path);
/// Parses and checks URDF text; `source` names it in errors ("ROBOT_DESCRIPTION from x@y:1").
RobotModel parseRobotModel(const std::string& urdf, const std::string& source);
/// Throws UrdfError when a name of `robot` cannot be sent (lcmtf::whyUnsendable()): its own, a
/// link's with `frame_prefix` before it, or a movable joint's, which joint states carry.
void requireSendableNames(const RobotModel& robot, const std::string& frame_prefix);

}  // namespace lcmtf::urdf
