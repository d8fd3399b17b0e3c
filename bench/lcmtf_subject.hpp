#pragma once

#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "tree_workload.hpp"

namespace bench {

// lcmtf::BufferCore behind the calls the benchmarks make.
class LcmtfSubject {
 public:
  static constexpr const char* kName = "lcmtf";

  explicit LcmtfSubject(const Workload& workload)
      : buffer_(lcmtf::Duration(workload.history())), names_(workload.names) {
    for (const Edge& edge : workload.edges) addEdge(names_[edge.parent], names_[edge.child]);
  }

  /// Resolves every frame's handle, once the frames are there (resolving makes a frame).
  void resolveHandles() {
    handles_.clear();
    for (const std::string& name : names_) handles_.push_back(buffer_.resolveFrame(name));
  }

  std::size_t addEdge(const std::string& parent, const std::string& child) {
    lcmtf::TransformStamped message;
    message.parent_frame = parent;
    message.child_frame = child;
    messages_.push_back(message);
    return messages_.size() - 1;
  }

  void set(std::size_t edge, std::int64_t stamp, const Pose& pose, bool is_static = false) {
    lcmtf::TransformStamped& message = messages_[edge];
    message.stamp = lcmtf::fromUtime(stamp);
    message.transform.translation = {pose.x, pose.y, pose.z};
    message.transform.rotation.coeffs() << pose.qx, pose.qy, pose.qz, pose.qw;
    buffer_.setTransform(message, authority_, is_static);
  }

  lcmtf::TransformStamped lookup(const Query& q) const {
    return buffer_.lookupTransform(names_[q.target], names_[q.source], lcmtf::fromUtime(q.time));
  }
  lcmtf::TransformStamped lookupLatest(const Query& q) const {
    return buffer_.lookupTransform(names_[q.target], names_[q.source], lcmtf::kLatestTime);
  }
  lcmtf::TransformStamped lookupTimeTravel(const Query& q) const {
    return buffer_.lookupTransform(names_[q.target], lcmtf::fromUtime(q.time), names_[q.source],
                                   lcmtf::fromUtime(q.other_time), names_[q.fixed]);
  }
  bool canTransform(const Query& q) const {
    return buffer_.canTransform(names_[q.target], names_[q.source], lcmtf::fromUtime(q.time));
  }
  lcmtf::TransformStamped lookupByHandle(const Query& q) const {
    return buffer_.lookupTransform(handles_[q.target], handles_[q.source],
                                   lcmtf::fromUtime(q.time));
  }

  void lookupByHandleInto(const Query& q, lcmtf::TransformStamped& result) const {
    buffer_.lookupTransform(handles_[q.target], handles_[q.source], lcmtf::fromUtime(q.time),
                            result);
  }

  static Pose pose(const lcmtf::TransformStamped& t) {
    const auto& p = t.transform.translation;
    const auto& r = t.transform.rotation;
    return Pose{p.x(), p.y(), p.z(), r.x(), r.y(), r.z(), r.w()};
  }

 private:
  lcmtf::BufferCore buffer_;
  std::vector<std::string> names_;
  std::vector<lcmtf::FrameHandle> handles_;
  std::vector<lcmtf::TransformStamped> messages_;
  const std::string authority_ = "robot_state_publisher";
};

}  // namespace bench
