#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace lcmtf_test {

/// A joint exactly as its URDF element says, read with TinyXML, independently of urdfdom and
/// of lcmtf's own model.
struct ReferenceJoint {
  std::string name;
  std::string type;
  std::string parent;
  std::string child;
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  ///< URDF's default when <axis> is absent
  bool has_limits = false;
  double lower = 0.0;
  double upper = 0.0;
  std::string mimic_leader;  ///< empty: not a mimic joint
  double multiplier = 1.0;
  double offset = 0.0;

  bool movable() const { return type == "revolute" || type == "continuous" || type == "prismatic"; }
  bool driven() const { return movable() && mimic_leader.empty(); }
};

/// The robot's joints and the test's own forward kinematics over them.
class ReferenceRobot {
 public:
  explicit ReferenceRobot(const std::string& path);

  const std::vector<ReferenceJoint>& joints() const { return joints_; }
  const std::string& root() const { return root_; }
  std::vector<std::string> links() const;
  const ReferenceJoint& jointToChild(const std::string& child) const;

  /// parent_T_child: origin (R = Rz(yaw) Ry(pitch) Rx(roll)), then the motion along or about
  /// the normalized axis by `position`.
  static Eigen::Isometry3d parentTChild(const ReferenceJoint& joint, double position);
  /// The position of any movable joint given those of the driven ones (mimics resolved).
  double positionOf(const ReferenceJoint& joint, const std::map<std::string, double>& driven) const;
  /// root_T_link by walking up from the link.
  Eigen::Isometry3d rootTLink(const std::string& link,
                              const std::map<std::string, double>& driven) const;

 private:
  std::vector<ReferenceJoint> joints_;
  std::map<std::string, std::size_t> joint_to_child_;
  std::map<std::string, std::size_t> by_name_;
  std::vector<std::string> links_;
  std::string root_;
};

}  // namespace lcmtf_test
