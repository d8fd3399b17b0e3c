#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <tf2/buffer_core.h>

#include <string>
#include <vector>

#include "tree_workload.hpp"

namespace bench {

// ROS tf2::BufferCore behind the calls the benchmarks make.
class Tf2Subject {
 public:
  static constexpr const char* kName = "tf2";

  explicit Tf2Subject(const Workload& workload)
      : buffer_(ros::Duration(static_cast<double>(workload.history()) * 1e-6)),
        names_(workload.names) {
    for (const Edge& edge : workload.edges) addEdge(names_[edge.parent], names_[edge.child]);
  }

  std::size_t addEdge(const std::string& parent, const std::string& child) {
    geometry_msgs::TransformStamped message;
    message.header.frame_id = parent;
    message.child_frame_id = child;
    messages_.push_back(message);
    return messages_.size() - 1;
  }

  void set(std::size_t edge, std::int64_t stamp, const Pose& pose, bool is_static = false) {
    geometry_msgs::TransformStamped& message = messages_[edge];
    message.header.stamp = rosTime(stamp);
    message.transform.translation.x = pose.x;
    message.transform.translation.y = pose.y;
    message.transform.translation.z = pose.z;
    message.transform.rotation.x = pose.qx;
    message.transform.rotation.y = pose.qy;
    message.transform.rotation.z = pose.qz;
    message.transform.rotation.w = pose.qw;
    buffer_.setTransform(message, authority_, is_static);
  }

  void resolveHandles() {}

  geometry_msgs::TransformStamped lookup(const Query& q) const {
    return buffer_.lookupTransform(names_[q.target], names_[q.source], rosTime(q.time));
  }
  geometry_msgs::TransformStamped lookupLatest(const Query& q) const {
    return buffer_.lookupTransform(names_[q.target], names_[q.source], ros::Time());
  }
  geometry_msgs::TransformStamped lookupTimeTravel(const Query& q) const {
    return buffer_.lookupTransform(names_[q.target], rosTime(q.time), names_[q.source],
                                   rosTime(q.other_time), names_[q.fixed]);
  }
  bool canTransform(const Query& q) const {
    return buffer_.canTransform(names_[q.target], names_[q.source], rosTime(q.time));
  }

  static Pose pose(const geometry_msgs::TransformStamped& t) {
    const auto& p = t.transform.translation;
    const auto& r = t.transform.rotation;
    return Pose{p.x, p.y, p.z, r.x, r.y, r.z, r.w};
  }

 private:
  static ros::Time rosTime(std::int64_t utime) {
    return ros::Time(static_cast<std::uint32_t>(utime / 1'000'000),
                     static_cast<std::uint32_t>(utime % 1'000'000 * 1000));
  }

  tf2::BufferCore buffer_;
  std::vector<std::string> names_;
  std::vector<geometry_msgs::TransformStamped> messages_;
  const std::string authority_ = "robot_state_publisher";
};

}  // namespace bench
