#include "lcmtf/nodes/tf_traffic_subscriber.hpp"

#include <exception>

#include "lcmtf/resend_request_t.hpp"

namespace lcmtf::nodes {

namespace {

// Messages LCM may queue per channel between two handle calls; bursts are counted, not lost.
// Fewer while messages come too large for that many to fit in the bytes (SubscriptionBudget).
constexpr int kQueueCapacity = 10000;
constexpr std::size_t kQueueBytes = std::size_t{256} << 20;

}  // namespace

TfTrafficSubscriber::TfTrafficSubscriber(lcm::LCM& lcm, const TfConnection& connection,
                                         TfTraffic& traffic, BatchObserver observer)
    : lcm_(lcm), connection_(connection), traffic_(traffic), observer_(std::move(observer)) {
  for (const std::string& channel : {connection_.tf_channel, connection_.static_channel}) {
    queues_.emplace_back(lcm_.subscribe(channel, &TfTrafficSubscriber::onMessage, this), channel,
                         kQueueBytes, kQueueCapacity);
  }
}

TfTrafficSubscriber::~TfTrafficSubscriber() {
  for (const SubscriptionBudget& queue : queues_) lcm_.unsubscribe(queue.subscription());
}

void TfTrafficSubscriber::requestStatics(const std::string& requester) {
  resend_request_t request;
  request.utime = toUtime(now());
  request.requester = requester;
  lcm_.publish(connection_.request_channel, &request);
}

void TfTrafficSubscriber::onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  fitChannel(queues_, channel, buffer->data_size);
  tf_message_t batch;
  const DecodeResult decoded = decodeMessage(buffer->data, buffer->data_size, batch);
  if (!decoded.ok) {
    traffic_.recordMalformed(channel, decoded.error);
    return;
  }
  const bool is_static = channel == connection_.static_channel;
  const TimePoint received = fromUtime(buffer->recv_utime);
  // Nothing may escape into LCM's C dispatch loop.
  try {
    traffic_.record(batch, is_static, received);
    if (observer_) observer_(batch, is_static, received);
  } catch (const std::exception& e) {
    traffic_.recordMalformed(channel, std::string("could not record: ") + e.what());
  }
}

}  // namespace lcmtf::nodes
