#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lcmtf/channels.hpp"
#include "lcmtf/joint_state_t.hpp"
#include "lcmtf/tf_message_t.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf/transform_stamped.hpp"
#include "lcmtf/wire_decode.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// How joint states become transform batches.
struct JointStateOptions {
  std::string frame_prefix;        ///< written before every link name, as is ("robot1/")
  bool ignore_timestamp = false;   ///< stamp transforms with the arrival time, not utime
  double publish_frequency = 0.0;  ///< Hz cap per joint on the stamps; 0 publishes every state
  std::string authority = defaultAuthority();  ///< signs every batch
  DecodeLimits limits;                         ///< bounds on incoming joint states
  /// Where the first problem of each kind (each unknown name, ...) is reported; null: nowhere.
  std::function<void(const std::string& message)> reporter;
};

/// What the processor has handled and refused since it started.
struct JointStateStatistics {
  std::uint64_t received = 0;              ///< joint states handled, refused ones included
  std::uint64_t batches = 0;               ///< transform batches produced
  std::uint64_t transforms = 0;            ///< transforms in those batches
  std::uint64_t malformed = 0;             ///< refused: the bytes did not decode
  std::uint64_t length_mismatches = 0;     ///< refused: names and positions differ in number
  std::uint64_t unstamped = 0;             ///< refused: utime zero or negative
  std::uint64_t rate_limited = 0;          ///< skipped: within the publish-frequency cap
  std::uint64_t non_finite_positions = 0;  ///< skipped: a NaN or infinite position or pose
  std::uint64_t unknown_joints = 0;        ///< entries naming no joint of the robot
  std::uint64_t ignored_joints = 0;        ///< entries naming a fixed, floating or planar joint
  /// Mimic joints' positions a joint state gave, published instead of the leader's relation.
  std::uint64_t given_mimic_positions = 0;
  std::uint64_t duplicate_joints = 0;  ///< entries repeating a joint of the same message
  std::uint64_t lost = 0;       ///< numbered joint states (joint_state_t::sequence) that never came
  std::uint64_t reordered = 0;  ///< numbered joint states that came after a higher number
  std::uint64_t duplicated = 0;  ///< numbered joint states that came again
};

/// One line: what was handled and, when there were any, what was refused and why.
std::string describe(const JointStateStatistics& statistics);

/// Each joint state as one batch of parent_T_child: its movable joints and their mimic joints.
/// A mimic joint whose position the joint state gives takes that position (as in
/// robot_state_publisher 2), else multiplier * leader + offset. Bad entries are skipped, bad
/// messages refused, each counted and first reported. One thread.
class JointStateProcessor {
 public:
  explicit JointStateProcessor(const RobotModel& robot, JointStateOptions options = {});
  ~JointStateProcessor();
  JointStateProcessor(const JointStateProcessor&) = delete;
  JointStateProcessor& operator=(const JointStateProcessor&) = delete;

  /// The batch for an encoded joint_state_t received at `arrival`, or null when there is
  /// nothing to publish. The batch (not numbered) stays valid until the next call.
  tf_message_t* process(const void* data, std::size_t size, TimePoint arrival = now());
  tf_message_t* process(const joint_state_t& state, TimePoint arrival = now());

  /// Publishes the joints of `robot` from now on (a new description); the counts go on.
  void setRobot(const RobotModel& robot);
  /// What has been handled and refused so far.
  const JointStateStatistics& statistics() const;
  /// The options it was made with.
  const JointStateOptions& options() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

/// The fixed joints of `robot` as static transforms, link names prefixed, stamped `stamp`.
std::vector<TransformStamped> fixedJointTransforms(const RobotModel& robot,
                                                   const std::string& frame_prefix,
                                                   TimePoint stamp = now());

}  // namespace lcmtf::urdf
