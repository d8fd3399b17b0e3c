#include "mimic_chains.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace lcmtf::urdf {

namespace {

std::string describeMissingLeader(const RobotModel& robot, const MovableJoint& follower) {
  const std::string& leader = follower.mimic->leader;
  const std::string start = "joint '" + follower.name + "' mimics '" + leader + "'";
  for (const FixedJoint& joint : robot.fixed_joints) {
    if (joint.name == leader) return start + ", a fixed joint, which has no position";
  }
  for (const UnsupportedJoint& joint : robot.unsupported_joints) {
    if (joint.name == leader) {
      return start + ", a " + joint.type + " joint, which has no single position";
    }
  }
  return start + ", which is not a joint of the robot";
}

std::string describeLoop(const std::vector<const MovableJoint*>& path, std::size_t loop_start) {
  std::string text = "mimic joints form a loop: ";
  for (std::size_t i = loop_start; i < path.size(); ++i) text += path[i]->name + " -> ";
  return text + path[loop_start]->name;
}

}  // namespace

void resolveMimicChains(RobotModel& robot) {
  std::unordered_map<std::string, const MovableJoint*> by_name;
  for (const MovableJoint& joint : robot.movable_joints) by_name.emplace(joint.name, &joint);

  std::vector<Mimic> resolved(robot.movable_joints.size());
  for (std::size_t j = 0; j < robot.movable_joints.size(); ++j) {
    const MovableJoint& follower = robot.movable_joints[j];
    if (!follower.mimic) continue;
    // value(follower) = multiplier * value(current) + offset, walking up the chain.
    double multiplier = 1.0;
    double offset = 0.0;
    std::vector<const MovableJoint*> path{&follower};
    const MovableJoint* current = &follower;
    while (current->mimic) {
      const auto leader = by_name.find(current->mimic->leader);
      if (leader == by_name.end()) {
        throw UrdfError(robot.source + ": " + describeMissingLeader(robot, *current));
      }
      offset += multiplier * current->mimic->offset;
      multiplier *= current->mimic->multiplier;
      const auto seen = std::find(path.begin(), path.end(), leader->second);
      if (seen != path.end()) {
        throw UrdfError(robot.source + ": " +
                        describeLoop(path, static_cast<std::size_t>(seen - path.begin())));
      }
      path.push_back(leader->second);
      current = leader->second;
    }
    if (!std::isfinite(multiplier) || !std::isfinite(offset)) {
      throw UrdfError(robot.source + ": the mimic chain from joint '" + follower.name + "' to '" +
                      current->name + "' multiplies out to a value beyond double range");
    }
    resolved[j] = Mimic{current->name, multiplier, offset};
  }
  for (std::size_t j = 0; j < robot.movable_joints.size(); ++j) {
    if (robot.movable_joints[j].mimic) robot.movable_joints[j].resolved_mimic = resolved[j];
  }
}

}  // namespace lcmtf::urdf
