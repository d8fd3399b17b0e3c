#include "lcmtf_urdf/urdf_publisher.hpp"

#include "lcmtf/resend_request_t.hpp"
#include "lcmtf/sendable_names.hpp"
#include "lcmtf/wire_decode.hpp"
#include "lcmtf_urdf/robot_description.hpp"

namespace lcmtf::urdf {

namespace {

StaticBroadcasterOptions staticOptions(const UrdfPublisherOptions& options) {
  StaticBroadcasterOptions statics;
  statics.channel = options.tf_static_channel;
  statics.request_channel = options.tf_static_request_channel;
  statics.authority = options.joint_states.authority;
  statics.resend_period = options.static_resend_period;
  return statics;
}

}  // namespace

UrdfPublisher::UrdfPublisher(lcm::LCM& lcm, RobotModel robot, UrdfPublisherOptions options)
    : lcm_(lcm),
      robot_(std::move(robot)),
      options_(std::move(options)),
      processor_(robot_, options_.joint_states),
      tf_numbering_(options_.tf_channel, options_.joint_states.authority),
      description_problems_(options_.joint_states.reporter) {
  // Before subscribing: a constructor that throws leaves nothing subscribed to it.
  requireSendable({}, options_.joint_states.authority);
  requireSendableNames(robot_, options_.joint_states.frame_prefix);
  joint_state_queue_.emplace(
      lcm_.subscribe(options_.joint_states_channel, &UrdfPublisher::onJointState, this),
      options_.joint_states_channel, options_.queue_bytes, options_.queue_capacity);
  if (options_.publish_description) {
    description_request_queue_.emplace(lcm_.subscribe(options_.description_request_channel,
                                                      &UrdfPublisher::onDescriptionRequest, this),
                                       options_.description_request_channel, kDefaultQueueBytes,
                                       kLcmDefaultQueueCapacity);
    publishDescription();
  }
  if (options_.follow_description) {
    description_queue_.emplace(
        lcm_.subscribe(options_.description_channel, &UrdfPublisher::onDescription, this),
        options_.description_channel, kDefaultQueueBytes, kLcmDefaultQueueCapacity);
  }
  publishStatics();
}

UrdfPublisher::~UrdfPublisher() {
  lcm_.unsubscribe(joint_state_queue_->subscription());
  if (description_request_queue_) lcm_.unsubscribe(description_request_queue_->subscription());
  if (description_queue_) lcm_.unsubscribe(description_queue_->subscription());
}

// A broadcaster of its own for each robot, so the statics of a robot replaced are sent no more.
void UrdfPublisher::publishStatics() {
  statics_.reset();
  statics_.emplace(lcm_, staticOptions(options_));
  const std::vector<TransformStamped> fixed =
      fixedJointTransforms(robot_, options_.joint_states.frame_prefix);
  if (!fixed.empty() && !statics_->sendTransform(fixed)) ++publish_failures_;
}

void UrdfPublisher::poll() {
  if (next_robot_) {
    robot_ = std::move(*next_robot_);
    next_robot_.reset();
    processor_.setRobot(robot_);
    publishStatics();
    ++robots_replaced_;
  }
  statics_->resendIfDue();
  answerDescriptionIfDue();
}

void UrdfPublisher::onDescription(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  description_queue_->fit(buffer->data_size);
  robot_description_t description;
  const DecodeResult decoded = decodeMessage(buffer->data, buffer->data_size, description);
  if (!decoded.ok) {
    ++descriptions_refused_;
    description_problems_.report(
        "malformed", "refused a message on " + channel + ": " + decoded.error + " (reported once)");
    return;
  }
  const std::string& current = next_robot_ ? next_robot_->urdf : robot_.urdf;
  if (description.urdf == current || description.urdf == refused_urdf_) return;
  try {
    RobotModel robot =
        parseRobotModel(description.urdf, channel + " from " + description.authority);
    requireSendableNames(robot, options_.joint_states.frame_prefix);
    next_robot_ = std::move(robot);
  } catch (const UrdfError& e) {
    ++descriptions_refused_;
    refused_urdf_ = description.urdf;
    description_problems_.report(e.what(), std::string("kept the robot, refused a new robot "
                                                       "description: ") +
                                               e.what());
  }
}

void UrdfPublisher::onJointState(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
  if (joint_state_queue_->fit(buffer->data_size)) ++joint_state_queue_shortened_;
  tf_message_t* batch = processor_.process(buffer->data, buffer->data_size);
  if (!batch) return;
  batch->sequence = tf_numbering_.next();
  if (lcm_.publish(options_.tf_channel, batch) != 0) ++publish_failures_;
}

void UrdfPublisher::onDescriptionRequest(const lcm::ReceiveBuffer* buffer,
                                         const std::string& /*channel*/) {
  description_request_queue_->fit(buffer->data_size);
  resend_request_t request;
  if (!decodeMessage(buffer->data, buffer->data_size, request).ok) return;
  ++description_requests_answered_;
  description_request_pending_ = true;
  answerDescriptionIfDue();
}

// A flood of requests must not turn into a flood of URDF texts.
void UrdfPublisher::answerDescriptionIfDue() {
  if (!description_request_pending_) return;
  const auto now_steady = std::chrono::steady_clock::now();
  if (description_answers_sent_ > 0 &&
      now_steady - last_description_answer_ < kDescriptionAnswerInterval) {
    return;
  }
  description_request_pending_ = false;
  last_description_answer_ = now_steady;
  ++description_answers_sent_;
  publishDescription();
}

void UrdfPublisher::publishDescription() {
  const robot_description_t description =
      makeRobotDescription(robot_, options_.joint_states.authority);
  if (lcm_.publish(options_.description_channel, &description) != 0) ++publish_failures_;
}

}  // namespace lcmtf::urdf
