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

std::string describeLoop(const RobotModel& robot, const std::vector<std::size_t>& path,
                         std::size_t loop_start) {
  std::string text = "mimic joints form a loop: ";
  for (std::size_t i = loop_start; i < path.size(); ++i) {
    text += robot.movable_joints[path[i]].name + " -> ";
  }
  return text + robot.movable_joints[path[loop_start]].name;
}

}  // namespace

void resolveMimicChains(RobotModel& robot) {
  const std::vector<MovableJoint>& joints = robot.movable_joints;
  std::unordered_map<std::string, std::size_t> index_of;
  for (std::size_t j = 0; j < joints.size(); ++j) index_of.emplace(joints[j].name, j);

  // Each joint is resolved once, from its leader's resolved relation, so a chain of any
  // length takes time in proportion to its length.
  enum class Progress { kNotYet, kOnTheWayUp, kResolved };
  std::vector<Progress> progress(joints.size(), Progress::kNotYet);
  std::vector<Mimic> resolved(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (!joints[j].mimic || progress[j] == Progress::kResolved) continue;
    std::vector<std::size_t> path;
    std::size_t current = j;
    while (joints[current].mimic && progress[current] != Progress::kResolved) {
      if (progress[current] == Progress::kOnTheWayUp) {
        const auto loop_start = std::find(path.begin(), path.end(), current) - path.begin();
        throw UrdfError(robot.source + ": " +
                        describeLoop(robot, path, static_cast<std::size_t>(loop_start)));
      }
      progress[current] = Progress::kOnTheWayUp;
      path.push_back(current);
      const auto leader = index_of.find(joints[current].mimic->leader);
      if (leader == index_of.end()) {
        throw UrdfError(robot.source + ": " + describeMissingLeader(robot, joints[current]));
      }
      current = leader->second;
    }
    // value(follower) = multiplier * value(leader) + offset, composed down from the top.
    Mimic above = joints[current].mimic ? resolved[current] : Mimic{joints[current].name};
    for (auto follower = path.rbegin(); follower != path.rend(); ++follower) {
      const Mimic& own = *joints[*follower].mimic;
      above = Mimic{above.leader, own.multiplier * above.multiplier,
                    own.multiplier * above.offset + own.offset};
      resolved[*follower] = above;
      progress[*follower] = Progress::kResolved;
    }
  }
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (!joints[j].mimic) continue;
    if (!std::isfinite(resolved[j].multiplier) || !std::isfinite(resolved[j].offset)) {
      throw UrdfError(robot.source + ": the mimic chain from joint '" + joints[j].name + "' to '" +
                      resolved[j].leader + "' multiplies out to a value beyond double range");
    }
  }
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (joints[j].mimic) robot.movable_joints[j].resolved_mimic = resolved[j];
  }
}

}  // namespace lcmtf::urdf
