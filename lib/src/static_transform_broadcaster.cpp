#include "lcmtf/static_transform_broadcaster.hpp"

#include <stdexcept>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/sendable_names.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/wire_decode.hpp"
#include "open_lcm.hpp"

namespace lcmtf {

namespace {

// Keeps each published batch well inside one UDP datagram.
constexpr int kMaxBatchBytes = 60000;

}  // namespace

StaticTransformBroadcaster::StaticTransformBroadcaster(StaticBroadcasterOptions options)
    : options_(std::move(options)),
      owned_lcm_(detail::openLcm(options_.lcm_url)),
      lcm_(*owned_lcm_),
      numbering_(options_.channel, options_.authority) {
  requireSendable({}, options_.authority);
  subscribeToRequests();
  thread_ = std::thread([this] { run(); });
}

StaticTransformBroadcaster::StaticTransformBroadcaster(lcm::LCM& lcm,
                                                       StaticBroadcasterOptions options)
    : options_(std::move(options)), lcm_(lcm), numbering_(options_.channel, options_.authority) {
  requireSendable({}, options_.authority);
  subscribeToRequests();
}

void StaticTransformBroadcaster::subscribeToRequests() {
  request_queue_.emplace(
      lcm_.subscribe(options_.request_channel, &StaticTransformBroadcaster::onRequest, this),
      options_.request_channel, kDefaultQueueBytes, kLcmDefaultQueueCapacity);
}

StaticTransformBroadcaster::~StaticTransformBroadcaster() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
  if (request_queue_) lcm_.unsubscribe(request_queue_->subscription());
}

bool StaticTransformBroadcaster::sendTransform(const TransformStamped& transform) {
  return sendTransform(std::vector<TransformStamped>{transform});
}

bool StaticTransformBroadcaster::sendTransform(const std::vector<TransformStamped>& transforms) {
  requireSendable(transforms, options_.authority);
  {
    std::lock_guard<std::mutex> guard(mutex_);
    for (const TransformStamped& transform : transforms) {
      transforms_[transform.child_frame] = transform;
    }
  }
  return publishAll();
}

std::size_t StaticTransformBroadcaster::size() const {
  std::lock_guard<std::mutex> guard(mutex_);
  return transforms_.size();
}

bool StaticTransformBroadcaster::publishAll() {
  const std::lock_guard<std::mutex> publishing(publish_mutex_);
  std::vector<tf_message_t> batches;
  {
    std::lock_guard<std::mutex> guard(mutex_);
    last_published_ = std::chrono::steady_clock::now();
    if (transforms_.empty()) return true;
    batches.push_back(makeTfMessage({}, options_.authority));
    int batch_bytes = batches.back().getEncodedSize();
    for (const auto& [child, transform] : transforms_) {
      transform_t message = toMessage(transform);
      const int bytes = message._getEncodedSizeNoHash();
      if (batch_bytes + bytes > kMaxBatchBytes && !batches.back().transforms.empty()) {
        batches.push_back(makeTfMessage({}, options_.authority));
        batch_bytes = batches.back().getEncodedSize();
      }
      batches.back().transforms.push_back(std::move(message));
      ++batches.back().num_transforms;
      batch_bytes += bytes;
    }
  }
  bool published = true;
  for (tf_message_t& batch : batches) {
    batch.sequence = numbering_.next();
    published = lcm_.publish(options_.channel, &batch) == 0 && published;
  }
  return published;
}

void StaticTransformBroadcaster::resendIfDue() {
  if (options_.resend_period <= Duration::zero()) return;
  bool due = false;
  {
    std::lock_guard<std::mutex> guard(mutex_);
    due = std::chrono::steady_clock::now() - last_published_ >= options_.resend_period;
  }
  if (due) publishAll();
}

void StaticTransformBroadcaster::onRequest(const lcm::ReceiveBuffer* buffer,
                                           const std::string& /*channel*/) {
  request_queue_->fit(buffer->data_size);
  resend_request_t request;
  if (!decodeMessage(buffer->data, buffer->data_size, request).ok) return;
  ++requests_answered_;
  publishAll();
}

void StaticTransformBroadcaster::run() {
  while (!stopping_) {
    lcm_.handleTimeout(20);
    resendIfDue();
  }
}

}  // namespace lcmtf
