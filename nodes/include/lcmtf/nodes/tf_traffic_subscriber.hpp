#pragma once

#include <functional>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/nodes/tf_connection.hpp"
#include "lcmtf/nodes/tf_traffic.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/subscription_budget.hpp"
#include "lcmtf/wire_decode.hpp"

namespace lcmtf::nodes {

/// Called after each batch is recorded, with the time LCM received it.
using BatchObserver =
    std::function<void(const tf_message_t& batch, bool is_static, TimePoint received)>;

/// Feeds a TfTraffic from the dynamic and static channels of an LCM that the caller handles,
/// decoding every message without trusting it.
class TfTrafficSubscriber {
 public:
  /// Subscribes on `lcm`; `lcm` and `traffic` must outlive the subscriber.
  TfTrafficSubscriber(lcm::LCM& lcm, const TfConnection& connection, TfTraffic& traffic,
                      BatchObserver observer = {});
  ~TfTrafficSubscriber();
  TfTrafficSubscriber(const TfTrafficSubscriber&) = delete;
  TfTrafficSubscriber& operator=(const TfTrafficSubscriber&) = delete;

  /// Asks every static broadcaster to send its transforms again now, signed `requester`.
  void requestStatics(const std::string& requester);

 private:
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  lcm::LCM& lcm_;
  TfConnection connection_;
  TfTraffic& traffic_;
  BatchObserver observer_;
  std::vector<SubscriptionBudget> queues_;
};

}  // namespace lcmtf::nodes
