#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/batch_numbering.hpp"
#include "lcmtf/channels.hpp"
#include "lcmtf/subscription_budget.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf {

/// Where and how often a StaticTransformBroadcaster publishes.
struct StaticBroadcasterOptions {
  std::string lcm_url;  ///< for the broadcaster's own LCM; "" is LCM's default
  std::string channel = kTfStaticChannel;
  std::string request_channel = kTfStaticRequestChannel;
  std::string authority = defaultAuthority();
  Duration resend_period = std::chrono::seconds(1);  ///< zero: only on change and on request
};

/// Publishes a set of static transforms, keyed by child frame: the whole set on every change,
/// at once when a listener asks on the request channel, and again every resend_period, so a
/// late joiner gets the static tree within milliseconds and a lost packet heals by itself.
class StaticTransformBroadcaster {
 public:
  /// Owns an LCM and a thread that answers requests and resends. Both constructors throw
  /// std::invalid_argument when the authority cannot be sent (whyUnsendable()).
  explicit StaticTransformBroadcaster(StaticBroadcasterOptions options = {});
  /// Uses the application's LCM: its handle loop delivers requests, and the application calls
  /// resendIfDue() from time to time. `lcm` must outlive the broadcaster.
  StaticTransformBroadcaster(lcm::LCM& lcm, StaticBroadcasterOptions options = {});
  ~StaticTransformBroadcaster();
  StaticTransformBroadcaster(const StaticTransformBroadcaster&) = delete;
  StaticTransformBroadcaster& operator=(const StaticTransformBroadcaster&) = delete;

  /// Adds or replaces the transforms of these child frames, then publishes the whole set.
  /// Throws std::invalid_argument, and keeps none of them, when a frame name cannot be sent
  /// (whyUnsendable()): the set would carry it in every batch from then on.
  bool sendTransform(const TransformStamped& transform);
  bool sendTransform(const std::vector<TransformStamped>& transforms);
  /// Publishes the whole set when resend_period has passed since it was last published.
  void resendIfDue();

  std::size_t size() const;
  const std::string& authority() const { return options_.authority; }
  /// Requests answered since construction.
  std::uint64_t requestsAnswered() const { return requests_answered_.load(); }

 private:
  void subscribeToRequests();
  void onRequest(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  bool publishAll();
  void run();

  StaticBroadcasterOptions options_;
  std::unique_ptr<lcm::LCM> owned_lcm_;
  lcm::LCM& lcm_;
  std::optional<SubscriptionBudget> request_queue_;
  BatchNumbering numbering_;
  std::mutex publish_mutex_;  // batches leave in the order of their numbers
  mutable std::mutex mutex_;
  std::map<std::string, TransformStamped> transforms_;
  std::chrono::steady_clock::time_point last_published_;
  std::atomic<std::uint64_t> requests_answered_{0};
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace lcmtf
