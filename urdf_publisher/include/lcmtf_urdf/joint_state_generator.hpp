#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lcmtf/joint_state_t.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// What positions a JointStateGenerator gives.
struct JointStateGeneratorOptions {
  bool sweep = false;         ///< move every joint; otherwise hold each at rest
  double sweep_period = 8.0;  ///< seconds for the slowest joint's swing or turn, roughly
  std::vector<std::pair<std::string, double>> held;  ///< joints kept at these positions
};

/// Joint states for every movable joint of a robot that follows no other: at rest, or
/// sweeping smoothly within the limits (continuous joints turn round and round); and, after
/// them, every mimic joint at the position its leader gives it.
class JointStateGenerator {
 public:
  /// Throws std::invalid_argument for a held joint that is unknown, a mimic joint, or held
  /// outside its limits or at a non-finite position.
  JointStateGenerator(const RobotModel& robot, JointStateGeneratorOptions options = {});

  /// The joints in the order of every state's arrays: those that follow no other, then the
  /// mimic joints.
  const std::vector<std::string>& jointNames() const { return names_; }
  /// How many of them are mimic joints.
  std::size_t mimicCount() const { return mimics_.size(); }
  /// Positions and velocities `elapsed_seconds` after the start, stamped `stamp`. A position
  /// in `given` (indexed as jointNames()) takes the place of the generated one; mimic joints
  /// then follow their leader's position, given or not, unless given themselves.
  joint_state_t stateAt(double elapsed_seconds, TimePoint stamp,
                        const std::vector<std::optional<double>>& given = {}) const;

  /// Zero, or the middle of the limits when zero lies outside them.
  static double restPosition(const MovableJoint& joint);

 private:
  struct Motion {
    double center = 0.0;
    double amplitude = 0.0;  ///< half the swing; zero holds the joint at `center`
    double turn_rate = 0.0;  ///< rad/s of a continuous joint that turns
    double angular_frequency = 0.0;
    double phase = 0.0;
    double lower = 0.0;
    double upper = 0.0;
  };

  struct Follower {
    std::size_t leader = 0;  ///< index into motions_
    Mimic relation;
  };

  std::vector<std::string> names_;
  std::vector<Motion> motions_;
  std::vector<Follower> mimics_;
};

}  // namespace lcmtf::urdf
