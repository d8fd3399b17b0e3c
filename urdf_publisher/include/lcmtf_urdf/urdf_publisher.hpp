#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/batch_numbering.hpp"
#include "lcmtf/channels.hpp"
#include "lcmtf/programs/report_once.hpp"
#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf/subscription_budget.hpp"
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
  /// A new robot_description_t on description_channel replaces the robot, as
  /// robot_state_publisher takes a changed robot_description (when it came from the network).
  bool follow_description = false;
  Duration static_resend_period = std::chrono::seconds(1);
  int queue_capacity = 1000;  ///< joint states LCM holds while the publisher is busy
  /// Bytes of joint states LCM may hold: fewer than queue_capacity while larger ones come
  /// (lcmtf::SubscriptionBudget).
  std::size_t queue_bytes = kDefaultQueueBytes;
};

/// robot_state_publisher on LCM: fixed joints as statics, each joint state as one TF batch, the
/// URDF text at start and on request. Driven by the handle loop of the LCM it is given.
class UrdfPublisher {
 public:
  /// Subscribes on `lcm` (which must outlive it) and publishes the statics and description.
  /// Throws, subscribing nothing, std::invalid_argument when the authority cannot be sent and
  /// UrdfError when a link with the frame prefix cannot (lcmtf::whyUnsendable()).
  UrdfPublisher(lcm::LCM& lcm, RobotModel robot, UrdfPublisherOptions options = {});
  ~UrdfPublisher();
  UrdfPublisher(const UrdfPublisher&) = delete;
  UrdfPublisher& operator=(const UrdfPublisher&) = delete;

  /// Resends the static transforms when their period is up, answers description requests held
  /// back by the answer rate, and takes a new description heard; call between handle() calls.
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
  /// Robots taken from new descriptions (follow_description), and descriptions refused.
  std::uint64_t robotsReplaced() const { return robots_replaced_; }
  std::uint64_t descriptionsRefused() const { return descriptions_refused_; }
  /// Times large joint states made LCM hold fewer of them (queue_bytes).
  std::uint64_t jointStateQueueShortened() const { return joint_state_queue_shortened_; }
  static constexpr std::chrono::milliseconds kDescriptionAnswerInterval{100};

 private:
  void onJointState(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void onDescriptionRequest(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void onDescription(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void publishDescription();
  void answerDescriptionIfDue();
  void publishStatics();

  lcm::LCM& lcm_;
  RobotModel robot_;
  UrdfPublisherOptions options_;
  JointStateProcessor processor_;
  BatchNumbering tf_numbering_;
  std::optional<StaticTransformBroadcaster> statics_;  // made again for a new robot
  std::optional<SubscriptionBudget> joint_state_queue_;
  std::optional<SubscriptionBudget> description_request_queue_;
  std::optional<SubscriptionBudget> description_queue_;
  std::optional<RobotModel> next_robot_;  // taken in poll(), outside LCM's dispatch
  std::string refused_urdf_;              // the last text refused, not parsed again
  std::uint64_t robots_replaced_ = 0;
  std::uint64_t descriptions_refused_ = 0;
  std::uint64_t joint_state_queue_shortened_ = 0;
  programs::OnceReporter description_problems_;
  std::uint64_t publish_failures_ = 0;
  std::uint64_t description_requests_answered_ = 0;
  std::uint64_t description_answers_sent_ = 0;
  bool description_request_pending_ = false;
  std::chrono::steady_clock::time_point last_description_answer_{};
};

}  // namespace lcmtf::urdf
