#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/channels.hpp"
#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf_urdf/joint_state_processor.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// The channels a UrdfPublisher uses and how it publishes.
struct UrdfPublisherOptions {
  JointStateOptions joint_states;  ///< prefix, timestamps, rate cap, authority, reporter
  std::string joint_states_channel = kJointStatesChannel;
  std::string tf_channel = kTfChannel;
  std::string tf_static_channel = kTfStaticChannel;
  std::string tf_static_request_channel = kTfStaticRequestChannel;
  std::string description_channel = kRobotDescriptionChannel;
  std::string description_request_channel = kRobotDescriptionRequestChannel;
  bool publish_description = true;  ///< off when the description came from the network
  Duration static_resend_period = std::chrono::seconds(1);
  int queue_capacity = 1000;  ///< joint states LCM holds while the publisher is busy
};

/// robot_state_publisher on LCM: the fixed joints once as static transforms, each joint state
/// as one batch on the TF channel, and the URDF text on the description channel at start and
/// whenever it is asked for. Driven by the handle loop of the LCM it is given.
class UrdfPublisher {
 public:
  /// Subscribes on `lcm` (which must outlive it) and publishes the statics and description.
  UrdfPublisher(lcm::LCM& lcm, RobotModel robot, UrdfPublisherOptions options = {});
  ~UrdfPublisher();
  UrdfPublisher(const UrdfPublisher&) = delete;
  UrdfPublisher& operator=(const UrdfPublisher&) = delete;

  /// Resends the static transforms when their period is up; call between handle() calls.
  void poll();

  const RobotModel& robot() const { return robot_; }
  const JointStateStatistics& statistics() const { return processor_.statistics(); }
  std::uint64_t publishFailures() const { return publish_failures_; }
  std::uint64_t descriptionRequestsAnswered() const { return description_requests_; }

 private:
  void onJointState(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void onDescriptionRequest(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void publishDescription();

  lcm::LCM& lcm_;
  RobotModel robot_;
  UrdfPublisherOptions options_;
  JointStateProcessor processor_;
  StaticTransformBroadcaster statics_;
  lcm::Subscription* joint_states_ = nullptr;
  lcm::Subscription* description_requests_subscription_ = nullptr;
  std::uint64_t publish_failures_ = 0;
  std::uint64_t description_requests_ = 0;
};

}  // namespace lcmtf::urdf
