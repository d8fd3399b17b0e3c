#include "lcmtf_urdf/robot_model.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string_view>

#include "lcmtf/frame_name.hpp"
#include "lcmtf/programs/number_text.hpp"
#include "lcmtf/sendable_names.hpp"
#include "lcmtf_urdf/urdfdom_parse.hpp"
#include "mimic_chains.hpp"

namespace lcmtf::urdf {

using programs::formatNumber;

namespace {

// Far beyond any robot, small enough that a device file or a mistaken path fails fast.
constexpr std::size_t kMaxUrdfBytes = std::size_t{64} << 20;
constexpr double kShortestAxis = 1e-12;

class ModelBuilder {
 public:
  ModelBuilder(const ::urdf::ModelInterface& urdf, RobotModel& robot)
      : urdf_(urdf), robot_(robot) {}

  void build() {
    robot_.name = urdf_.getName();
    robot_.root_link = urdf_.getRoot()->name;
    checkNames();
    walkTreeFromRoot();
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw UrdfError(robot_.source + ": " + problem);
  }

  void checkNames() const {
    std::map<std::string_view, const std::string*> link_of_frame;
    for (const auto& [name, link] : urdf_.links_) {
      if (name.empty()) fail("a link has an empty name");
      const std::string_view frame = canonicalFrameName(name);
      if (frame.empty()) fail("link '/' names no frame (frame names drop one leading '/')");
      const auto [seen, added] = link_of_frame.emplace(frame, &name);
      if (!added) {
        fail("links '" + *seen->second + "' and '" + name + "' are the same frame '" +
             std::string(frame) + "' (frame names drop one leading '/')");
      }
    }
    for (const auto& [name, joint] : urdf_.joints_) {
      if (name.empty()) fail("a joint has an empty name");
    }
  }

  // Depth first from the root with an explicit stack, so a very deep chain cannot overflow
  // the call stack; children in the order urdfdom lists them.
  void walkTreeFromRoot() {
    std::vector<const ::urdf::Link*> pending{urdf_.getRoot().get()};
    while (!pending.empty()) {
      const ::urdf::Link* link = pending.back();
      pending.pop_back();
      robot_.links.push_back(link->name);
      if (link->parent_joint) addJoint(*link->parent_joint);
      for (auto child = link->child_links.rbegin(); child != link->child_links.rend(); ++child) {
        pending.push_back(child->get());
      }
    }
  }

  Transform origin(const ::urdf::Joint& joint) const {
    const ::urdf::Pose& pose = joint.parent_to_joint_origin_transform;
    const Eigen::Vector3d translation(pose.position.x, pose.position.y, pose.position.z);
    const Eigen::Quaterniond rotation(pose.rotation.w, pose.rotation.x, pose.rotation.y,
                                      pose.rotation.z);
    if (!translation.allFinite() || !rotation.coeffs().allFinite() ||
        rotation.norm() < kShortestAxis) {
      fail("joint '" + joint.name + "' has an origin that is not a finite pose");
    }
    return Transform(translation, rotation.normalized());
  }

  Eigen::Vector3d unitAxis(const ::urdf::Joint& joint) const {
    const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    const double length = axis.allFinite() ? axis.stableNorm() : 0.0;
    if (!(length >= kShortestAxis) || !std::isfinite(length)) {
      fail("joint '" + joint.name + "' has a zero axis (" + formatNumber(axis.x()) + " " +
           formatNumber(axis.y()) + " " + formatNumber(axis.z()) +
           "): it cannot say which way the joint moves");
    }
    return axis / length;
  }

  std::optional<PositionLimits> limits(const ::urdf::Joint& joint) const {
    if (joint.type == ::urdf::Joint::CONTINUOUS || !joint.limits) return std::nullopt;
    const PositionLimits limits{joint.limits->lower, joint.limits->upper};
    if (!std::isfinite(limits.lower) || !std::isfinite(limits.upper)) {
      fail("joint '" + joint.name + "' has limits that are not finite");
    }
    if (limits.lower > limits.upper) {
      fail("joint '" + joint.name + "' has its lower limit " + formatNumber(limits.lower) +
           " above its upper limit " + formatNumber(limits.upper));
    }
    return limits;
  }

  void addJoint(const ::urdf::Joint& joint) {
    switch (joint.type) {
      case ::urdf::Joint::FIXED:
        robot_.fixed_joints.push_back(
            {joint.name, joint.parent_link_name, joint.child_link_name, origin(joint)});
        return;
      case ::urdf::Joint::FLOATING:
      case ::urdf::Joint::PLANAR:
        robot_.unsupported_joints.push_back(
            {joint.name, joint.type == ::urdf::Joint::FLOATING ? "floating" : "planar",
             joint.parent_link_name, joint.child_link_name});
        return;
      case ::urdf::Joint::REVOLUTE:
      case ::urdf::Joint::CONTINUOUS:
      case ::urdf::Joint::PRISMATIC:
        addMovableJoint(joint);
        return;
      default:
        fail("joint '" + joint.name + "' has a type lcmtf does not know");
    }
  }

  void addMovableJoint(const ::urdf::Joint& joint) {
    MovableJoint movable;
    movable.name = joint.name;
    movable.parent_link = joint.parent_link_name;
    movable.child_link = joint.child_link_name;
    movable.motion = joint.type == ::urdf::Joint::REVOLUTE     ? JointMotion::kRevolute
                     : joint.type == ::urdf::Joint::CONTINUOUS ? JointMotion::kContinuous
                                                               : JointMotion::kPrismatic;
    movable.parent_T_origin = origin(joint);
    movable.axis = unitAxis(joint);
    movable.limits = limits(joint);
    if (joint.mimic) {
      movable.mimic = Mimic{joint.mimic->joint_name, joint.mimic->multiplier, joint.mimic->offset};
      if (!std::isfinite(movable.mimic->multiplier) || !std::isfinite(movable.mimic->offset)) {
        fail("joint '" + joint.name + "' has a mimic multiplier or offset that is not finite");
      }
    }
    robot_.movable_joints.push_back(std::move(movable));
  }

  const ::urdf::ModelInterface& urdf_;
  RobotModel& robot_;
};

std::string readWholeFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw UrdfError(path + ": cannot open: " + std::strerror(errno));
  std::string text;
  std::error_code not_regular;
  const std::uintmax_t size = std::filesystem::file_size(path, not_regular);
  if (!not_regular) text.reserve(std::min<std::uintmax_t>(size, kMaxUrdfBytes + 1));
  char chunk[65536];
  while (file.read(chunk, sizeof chunk) || file.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(file.gcount()));
    if (text.size() > kMaxUrdfBytes) {
      throw UrdfError(path + ": larger than " + std::to_string(kMaxUrdfBytes >> 20) +
                      " MiB, which is no URDF");
    }
  }
  if (file.bad()) throw UrdfError(path + ": cannot read: " + std::strerror(errno));
  return text;
}

}  // namespace

const char* toString(JointMotion motion) {
  switch (motion) {
    case JointMotion::kRevolute:
      return "revolute";
    case JointMotion::kContinuous:
      return "continuous";
    case JointMotion::kPrismatic:
      return "prismatic";
  }
  return "unknown";
}

const MovableJoint* RobotModel::findMovableJoint(const std::string& joint_name) const {
  for (const MovableJoint& joint : movable_joints) {
    if (joint.name == joint_name) return &joint;
  }
  return nullptr;
}

RobotModel loadRobotModel(const std::string& path) {
  return parseRobotModel(readWholeFile(path), path);
}

RobotModel parseRobotModel(const std::string& urdf, const std::string& source) {
  const ::urdf::ModelInterfaceSharedPtr parsed = parseWithUrdfdom(urdf, source);
  RobotModel robot;
  robot.source = source;
  robot.urdf = urdf;
  ModelBuilder(*parsed, robot).build();
  resolveMimicChains(robot);
  requireSendableNames(robot, "");
  return robot;
}

void requireSendableNames(const RobotModel& robot, const std::string& frame_prefix) {
  const auto require = [&robot](std::string_view what, const std::string& name) {
    const std::string problem = unsendableNameProblem(what, name);
    if (!problem.empty()) throw UrdfError(robot.source + ": " + problem);
  };
  require("robot name", robot.name);
  for (const std::string& link : robot.links) {
    require(frame_prefix.empty() ? "link" : "frame prefix and link", frame_prefix + link);
  }
  for (const MovableJoint& joint : robot.movable_joints) require("joint", joint.name);
}

}  // namespace lcmtf::urdf
