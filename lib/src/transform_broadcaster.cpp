#include "lcmtf/transform_broadcaster.hpp"

#include <stdexcept>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/sendable_names.hpp"
#include "open_lcm.hpp"

namespace lcmtf {

tf_message_t makeTfMessage(const std::vector<TransformStamped>& transforms,
                           const std::string& authority, TimePoint sent) {
  tf_message_t message{};
  message.utime = toUtime(sent);
  message.authority = authority;
  message.transforms.reserve(transforms.size());
  for (const TransformStamped& transform : transforms) {
    message.transforms.push_back(toMessage(transform));
  }
  message.num_transforms = static_cast<std::int32_t>(message.transforms.size());
  return message;
}

TransformBroadcaster::TransformBroadcaster(lcm::LCM& lcm, std::string channel,
                                           std::string authority)
    : lcm_(lcm),
      channel_(std::move(channel)),
      authority_(std::move(authority)),
      numbering_(channel_, authority_) {
  requireSendable({}, authority_);
}

TransformBroadcaster::TransformBroadcaster(const std::string& lcm_url, std::string channel,
                                           std::string authority)
    : owned_lcm_(detail::openLcm(lcm_url)),
      lcm_(*owned_lcm_),
      channel_(std::move(channel)),
      authority_(std::move(authority)),
      numbering_(channel_, authority_) {
  requireSendable({}, authority_);
}

bool TransformBroadcaster::sendTransform(const TransformStamped& transform) {
  return sendTransform(std::vector<TransformStamped>{transform});
}

bool TransformBroadcaster::sendTransform(const std::vector<TransformStamped>& transforms) {
  requireSendable(transforms, authority_);
  tf_message_t message = makeTfMessage(transforms, authority_);
  message.sequence = numbering_.next();
  return lcm_.publish(channel_, &message) == 0;
}

}  // namespace lcmtf
