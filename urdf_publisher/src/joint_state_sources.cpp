#include "lcmtf_urdf/joint_state_sources.hpp"

#include <cmath>

#include "lcmtf/wire_decode.hpp"

namespace lcmtf::urdf {

JointStateSources::JointStateSources(lcm::LCM& lcm, const std::vector<std::string>& channels,
                                     const std::vector<std::string>& joint_names)
    : lcm_(lcm), positions_(joint_names.size()) {
  for (std::size_t i = 0; i < joint_names.size(); ++i) index_of_[joint_names[i]] = i;
  for (const std::string& channel : channels) {
    queues_.emplace_back(lcm_.subscribe(channel, &JointStateSources::onMessage, this), channel,
                         kDefaultQueueBytes, kLcmDefaultQueueCapacity);
  }
}

JointStateSources::~JointStateSources() {
  for (const SubscriptionBudget& queue : queues_) lcm_.unsubscribe(queue.subscription());
}

void JointStateSources::onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  fitChannel(queues_, channel, buffer->data_size);
  take(buffer->data, buffer->data_size);
}

void JointStateSources::take(const void* data, std::size_t size) {
  if (!decodeMessage(data, size, decoded_).ok || decoded_.name.size() != decoded_.position.size()) {
    ++malformed_;
    return;
  }
  for (std::size_t i = 0; i < decoded_.name.size(); ++i) {
    const auto found = index_of_.find(decoded_.name[i]);
    if (found == index_of_.end()) {
      ++unknown_joints_;
    } else if (std::isfinite(decoded_.position[i])) {
      positions_[found->second] = decoded_.position[i];
    }
  }
}

}  // namespace lcmtf::urdf
