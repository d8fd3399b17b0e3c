#pragma once

// The batches a robot's state publisher sends, for the benchmarks and the profile training:
// the next sample of every dynamic edge of a workload's tree, as TransformStamped values and as
// the bytes of the tf_message_t a TransformBroadcaster would send.

#include <cstdint>
#include <vector>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "tree_workload.hpp"

namespace bench {

inline lcmtf::Transform transformOf(const Pose& p) {
  return lcmtf::Transform(Eigen::Vector3d(p.x, p.y, p.z),
                          Eigen::Quaterniond(p.qw, p.qx, p.qy, p.qz));
}

// A state publisher's batch for each step of the workload's motion: the step's sample of every
// dynamic edge, with the poses the insert rows of buffer_core_bench give.
class Publisher {
 public:
  explicit Publisher(const Workload& w) : w_(w), dynamic_(dynamicEdges(w)) {
    for (std::size_t index : dynamic_) {
      const Edge& edge = w.edges[index];
      batch_.push_back(lcmtf::TransformStamped{lcmtf::TimePoint{}, w.names[edge.parent],
                                               w.names[edge.child], lcmtf::Transform::identity()});
    }
  }

  std::size_t batchSize() const { return batch_.size(); }

  const std::vector<lcmtf::TransformStamped>& batch(std::size_t step) {
    for (std::size_t i = 0; i < dynamic_.size(); ++i) {
      const Edge& edge = w_.edges[dynamic_[i]];
      batch_[i].stamp = lcmtf::fromUtime(w_.stamp(edge, step));
      batch_[i].transform = transformOf(insertedPose(edge, step));
    }
    return batch_;
  }

  const std::vector<std::uint8_t>& encoded(std::size_t step) {
    lcmtf::tf_message_t message = lcmtf::makeTfMessage(batch(step), "robot_state_publisher");
    message.sequence = static_cast<std::int64_t>(step + 1);
    bytes_.resize(static_cast<std::size_t>(message.getEncodedSize()));
    message.encode(bytes_.data(), 0, static_cast<int>(bytes_.size()));
    return bytes_;
  }

 private:
  const Workload& w_;
  std::vector<std::size_t> dynamic_;
  std::vector<lcmtf::TransformStamped> batch_;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace bench
