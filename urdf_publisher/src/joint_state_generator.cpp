#include "lcmtf_urdf/joint_state_generator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "lcmtf/programs/closest_names.hpp"
#include "lcmtf/programs/number_text.hpp"
#include "lcmtf_urdf/joint_motion.hpp"

namespace lcmtf::urdf {

using programs::formatNumber;

namespace {

constexpr double kTwoPi = 6.283185307179586;
// Spreads the joints' phases evenly around the circle, whatever their number.
constexpr double kGoldenAngle = 2.399963229728653;

std::map<std::string, double> checkedHeld(const RobotModel& robot,
                                          const JointStateGeneratorOptions& options) {
  std::map<std::string, double> held;
  for (const auto& [name, position] : options.held) {
    const MovableJoint* joint = robot.findMovableJoint(name);
    if (!joint) {
      std::vector<std::string> movable;
      for (const MovableJoint& each : robot.movable_joints) movable.push_back(each.name);
      throw std::invalid_argument("robot '" + robot.name + "' has no movable joint '" + name + "'" +
                                  programs::didYouMean(name, movable));
    }
    if (joint->resolved_mimic) {
      throw std::invalid_argument("joint '" + name + "' is a mimic joint: it follows '" +
                                  joint->resolved_mimic->leader + "'");
    }
    if (!std::isfinite(position)) {
      throw std::invalid_argument("joint '" + name + "' cannot be held at " +
                                  formatNumber(position));
    }
    if (joint->limits && (position < joint->limits->lower || position > joint->limits->upper)) {
      throw std::invalid_argument("joint '" + name + "' cannot be held at " +
                                  formatNumber(position) + ", outside its limits [" +
                                  formatNumber(joint->limits->lower) + ", " +
                                  formatNumber(joint->limits->upper) + "]");
    }
    held[name] = position;
  }
  return held;
}

}  // namespace

double JointStateGenerator::restPosition(const MovableJoint& joint) {
  if (!joint.limits || (joint.limits->lower <= 0.0 && 0.0 <= joint.limits->upper)) return 0.0;
  return 0.5 * (joint.limits->lower + joint.limits->upper);
}

JointStateGenerator::JointStateGenerator(const RobotModel& robot,
                                         JointStateGeneratorOptions options) {
  if (!(options.sweep_period > 0.0) || !std::isfinite(options.sweep_period)) {
    throw std::invalid_argument("the sweep period must be a positive number of seconds");
  }
  const std::map<std::string, double> held = checkedHeld(robot, options);
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  for (const MovableJoint& joint : robot.movable_joints) {
    if (joint.resolved_mimic) continue;
    const std::size_t j = names_.size();
    names_.push_back(joint.name);
    Motion motion;
    motion.lower = joint.limits ? joint.limits->lower : -kInfinity;
    motion.upper = joint.limits ? joint.limits->upper : kInfinity;
    const auto pinned = held.find(joint.name);
    motion.center = pinned != held.end() ? pinned->second : restPosition(joint);
    if (options.sweep && pinned == held.end()) {
      // Periods between 0.6 and 1 times the sweep period, so joints do not move in lockstep.
      const double period = options.sweep_period * (0.6 + 0.1 * static_cast<double>(j % 5));
      motion.angular_frequency = kTwoPi / period;
      motion.phase = kGoldenAngle * static_cast<double>(j);
      if (joint.limits) {
        motion.center = 0.5 * (joint.limits->lower + joint.limits->upper);
        motion.amplitude = 0.5 * (joint.limits->upper - joint.limits->lower);
      } else {
        motion.turn_rate = (j % 2 == 0 ? 1.0 : -1.0) * motion.angular_frequency;
      }
    }
    motions_.push_back(motion);
  }
  for (const MovableJoint& joint : robot.movable_joints) {
    if (!joint.resolved_mimic) continue;
    const auto leader = std::find(names_.begin(), names_.end(), joint.resolved_mimic->leader);
    mimics_.push_back({static_cast<std::size_t>(leader - names_.begin()), *joint.resolved_mimic});
  }
  for (const MovableJoint& joint : robot.movable_joints) {
    if (joint.resolved_mimic) names_.push_back(joint.name);
  }
}

joint_state_t JointStateGenerator::stateAt(double elapsed_seconds, TimePoint stamp,
                                           const std::vector<std::optional<double>>& given) const {
  const auto givenAt = [&given](std::size_t j) {
    return j < given.size() ? given[j] : std::optional<double>();
  };
  joint_state_t state{};
  state.utime = toUtime(stamp);
  state.name = names_;
  state.position.reserve(motions_.size());
  state.velocity.reserve(motions_.size());
  // A position given from elsewhere comes without a velocity: zero is said for it.
  for (std::size_t j = 0; j < motions_.size(); ++j) {
    const Motion& m = motions_[j];
    const double angle = m.phase + m.angular_frequency * elapsed_seconds;
    const double position =
        m.center + m.amplitude * std::sin(angle) + m.turn_rate * elapsed_seconds;
    const std::optional<double> from_elsewhere = givenAt(j);
    state.position.push_back(from_elsewhere ? *from_elsewhere
                                            : std::clamp(position, m.lower, m.upper));
    state.velocity.push_back(
        from_elsewhere ? 0.0 : m.amplitude * m.angular_frequency * std::cos(angle) + m.turn_rate);
  }
  for (std::size_t f = 0; f < mimics_.size(); ++f) {
    const Follower& follower = mimics_[f];
    const std::optional<double> from_elsewhere = givenAt(motions_.size() + f);
    state.position.push_back(
        from_elsewhere ? *from_elsewhere
                       : mimicPosition(follower.relation, state.position[follower.leader]));
    state.velocity.push_back(
        from_elsewhere ? 0.0 : follower.relation.multiplier * state.velocity[follower.leader]);
  }
  state.num_joints = static_cast<std::int32_t>(state.name.size());
  state.num_positions = static_cast<std::int32_t>(state.position.size());
  state.num_velocities = static_cast<std::int32_t>(state.velocity.size());
  state.num_efforts = 0;
  return state;
}

}  // namespace lcmtf::urdf
