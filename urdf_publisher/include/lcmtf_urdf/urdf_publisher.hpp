#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/batch_numbering.hpp"
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

/// robot_state_publisher on LCM: fixed joints as statics, each joint state as one TF batch, the
/// URDF text at start and on request. Driven by the handle loop of the LCM it is given.
class UrdfPublisher {
 public:
  /// Subscribes on `lcm` (which must outlive it) and publishes the statics and description.
  UrdfPublisher(lcm::LCM& lcm, RobotModel robot, UrdfPublisherOptions options = {});
  ~UrdfPublisher();
  UrdfPublisher(const UrdfPublisher&) = delete;
  UrdfPublisher& operator=(const UrdfPublisher&) = delete;

  /// Resends the static transforms when their period is up, and answers description requests
  /// held back by the answer rate; call between handle() calls.
  void poll();

  /// The robot it publishes.
  const RobotModel& robot() const { return robot_; }
  /// The joint states handled and refused so far.
  const JointStateStatistics& statistics() const { return processor_.statistics(); }
  /// Publications LCM refused (batches, statics, descriptions).
  std::uint64_t publishFailures() const { return publish_failures_; }
  /// Requests for the URDF text received; requests that come together share one answer.
  std::uint64_t descriptionRequestsAnswered() const { return description_requests_answered_; }
  /// Answers sent to them: at most one per kDescriptionAnswerInterval.
  std::uint64_t descriptionAnswersSent() const { return description_answers_sent_; }
  static constexpr std::chrono::milliseconds kDescriptionAnswerInterval{100};

 private:
  void onJointState(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void onDescriptionRequest(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void publishDescription();
  void answerDescriptionIfDue();

  lcm::LCM& lcm_;
  RobotModel robot_;
  UrdfPublisherOptions options_;
  JointStateProcessor processor_;
  BatchNumbering tf_numbering_;
  StaticTransformBroadcaster statics_;
  lcm::Subscription* joint_state_subscription_ = nullptr;
  lcm::Subscription* description_request_subscription_ = nullptr;
  std::uint64_t publish_failures_ = 0;
  std::uint64_t description_requests_answered_ = 0;
  std::uint64_t description_answers_sent_ = 0;
  bool description_request_pending_ = false;
  std::chrono::steady_clock::time_point last_description_answer_{};
};

}  // namespace lcmtf::urdf
