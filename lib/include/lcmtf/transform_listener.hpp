#pragma once

#include <atomic>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/buffer.hpp"
#include "lcmtf/channels.hpp"
#include "lcmtf/subscription_budget.hpp"
#include "lcmtf/wire_decode.hpp"

namespace lcmtf {

namespace detail {
class ListenerAuthorities;
struct HeardAuthority;
}  // namespace detail

/// How far ahead of this machine's clock a listener accepts stamps by default: more than the
/// clocks of a robot's computers differ, no more than the buffer's default cache time.
inline constexpr Duration kDefaultMaxStampAhead = std::chrono::seconds(10);

/// What a TransformListener listens to and what it accepts.
struct ListenerOptions {
  std::string lcm_url;  ///< for the listener's own LCM; "" is LCM's default
  std::string channel = kTfChannel;
  std::string static_channel = kTfStaticChannel;
  std::string static_request_channel = kTfStaticRequestChannel;
  bool static_only = false;                      ///< ignore the dynamic channel
  std::vector<std::string> allowed_authorities;  ///< empty: accept every sender
  std::size_t max_frames = 10000;                ///< new frame names beyond this are refused
  /// Senders followed; a new one forgets one heard least recently, a sender heard only once first.
  std::size_t max_authorities = 1000;
  DecodeLimits limits;        ///< bounds on incoming messages
  int queue_capacity = 1000;  ///< messages LCM queues per channel
  /// Bytes of messages LCM may hold per channel waiting to be handled: while larger messages
  /// come, fewer than queue_capacity are held (see README, *Bounds*).
  std::size_t queue_bytes = kDefaultQueueBytes;
  std::string authority = defaultAuthority();  ///< names this listener in its requests
  bool request_statics_at_start = true;  ///< false: the owner calls requestStatics() when ready
  /// When not zero, set on the buffer at start (BufferCore::setMaxInterpolationGap): lookups
  /// between samples further apart, as after lost batches, fail instead of interpolating.
  Duration max_interpolation_gap = Duration::zero();
  /// Dynamic transforms stamped further than this ahead of this machine's clock when they come
  /// are refused (stamped_ahead): stored, one would make its edge refuse every sample of its
  /// publishers until that time, as it holds only the cache time behind its newest sample.
  /// Zero: no limit (a simulation whose clock runs ahead of the wall clock).
  Duration max_stamp_ahead = kDefaultMaxStampAhead;
  /// Where the first message of each kind the listener refuses is reported; null: nowhere.
  /// Default: stderr. Transforms the buffer refuses go to the buffer's own reporter
  /// (BufferCore::setErrorReporter). It is called on the thread that handled the message (the
  /// listener's own, which cannot destroy the listener: see onItsThread), after the listener's
  /// lock is released, so it may call statistics(). What it throws is written to stderr.
  std::function<void(const std::string& message)> reporter = [](const std::string& message) {
    std::cerr << "lcmtf listener: " << message << '\n';
  };
};

/// What a listener heard from one sender (on both channels) since it began following it.
struct AuthorityStatistics {
  std::string authority;
  std::uint64_t batches = 0;            ///< received from it, stale ones included
  std::uint64_t lost_batches = 0;       ///< numbers skipped (tf_message_t::sequence), not yet come
  std::uint64_t reordered_batches = 0;  ///< came after a higher number
  std::uint64_t duplicated_batches = 0;
  std::uint64_t sequence_restarts = 0;  ///< its numbers began again: restarted, or a log replayed
  std::uint64_t stale_batches = 0;      ///< dropped: older than the cache time behind its newest
  std::uint64_t history_resets = 0;     ///< its time jumped back for good: its edges cleared
  std::uint64_t cleared_edges = 0;      ///< edges whose dynamic history those resets dropped
  std::uint64_t resets_held_back = 0;   ///< jumps back dropped: it reset within the cache time
  std::uint64_t stamped_ahead = 0;      ///< transforms refused: stamped beyond max_stamp_ahead
};

/// What a listener has received and refused since it started.
struct ListenerStatistics {
  std::uint64_t messages = 0;             ///< batches decoded and accepted
  std::uint64_t transforms = 0;           ///< transforms stored in the buffer
  std::uint64_t malformed = 0;            ///< messages that failed to decode
  std::uint64_t rejected_transforms = 0;  ///< transforms the buffer refused (see its statistics)
  std::uint64_t unauthorized = 0;         ///< batches from authorities not allowed
  std::uint64_t frame_limit = 0;          ///< transforms refused by max_frames
  std::uint64_t stale_batches = 0;        ///< dropped: older than the cache time behind the newest
  std::uint64_t history_resets = 0;    ///< a sender's time jumped back for good: its edges cleared
  std::uint64_t cleared_edges = 0;     ///< edges whose dynamic history those resets dropped
  std::uint64_t resets_held_back = 0;  ///< jumps back dropped: that sender reset not long ago
  std::uint64_t lost_batches = 0;      ///< over all senders, as in AuthorityStatistics
  std::uint64_t reordered_batches = 0;
  std::uint64_t duplicated_batches = 0;
  std::uint64_t sequence_restarts = 0;
  std::uint64_t authorities_followed = 0;   ///< now, at most max_authorities
  std::uint64_t authorities_forgotten = 0;  ///< to make room for new ones (their counts stay here)
  std::uint64_t queue_shortened = 0;  ///< times large messages made LCM hold fewer for a channel
  std::uint64_t stamped_ahead = 0;    ///< transforms refused: stamped beyond max_stamp_ahead
};

/// Feeds a Buffer from the TF and TF_STATIC channels, and asks static broadcasters to resend
/// when it starts. Nothing from the network can crash it or corrupt the buffer: bad input is
/// counted in statistics() and reported once per kind.
class TransformListener {
 public:
  /// Owns an LCM on options.lcm_url and a thread that handles it.
  explicit TransformListener(Buffer& buffer, ListenerOptions options = {});
  /// Subscribes on the application's LCM; the application's handle loop drives the listener.
  /// `lcm` must outlive the listener.
  TransformListener(Buffer& buffer, lcm::LCM& lcm, ListenerOptions options = {});
  ~TransformListener();
  TransformListener(const TransformListener&) = delete;
  TransformListener& operator=(const TransformListener&) = delete;

  /// Asks every static broadcaster to resend its set now.
  void requestStatics();
  /// Stops handling messages now, from any thread, its own (inside its reporter) included:
  /// those still queued are dropped and the reporter is not called again. The destructor then
  /// only waits for its thread to end.
  void stop() { stopping_ = true; }
  ListenerStatistics statistics() const;
  /// Per sender followed now: those heard more than once first, each group the most recent first.
  std::vector<AuthorityStatistics> authorityStatistics() const;

  /// Whether the caller is the thread the listener owns, as its reporter is: the listener must
  /// be destroyed from another thread, as its destructor waits for that one to end.
  bool onItsThread() const { return std::this_thread::get_id() == thread_.get_id(); }

  /// Handles one encoded tf_message_t as if it had arrived on `channel` (replay, tests); from
  /// any thread, beside the listener's own handling.
  void handleMessage(const void* data, std::size_t size, const std::string& channel);

 private:
  void subscribe();
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void fitQueue(const std::string& channel, std::size_t message_size);
  struct Scratch;
  class ScratchLease;
  void handleBatch(const tf_message_t& batch, bool is_static,
                   std::vector<TransformStamped>& accepted);
  bool allowed(const std::string& authority) const;
  bool admitNewFrames(const transform_t& message, std::size_t& frames,
                      std::set<std::string>& added) const;
  detail::HeardAuthority& hear(const tf_message_t& batch, bool is_static);
  std::int64_t newestAllowedStamp() const;
  bool isStale(const tf_message_t& batch, std::int64_t newest_allowed,
               detail::HeardAuthority& sender);
  void refuseStampedAhead(const transform_t& message, std::int64_t newest_allowed,
                          const std::string& authority, detail::HeardAuthority& sender);
  void restartHistory(const tf_message_t& batch, std::int64_t batch_newest,
                      detail::HeardAuthority& sender);
  std::int64_t newestStored(const tf_message_t& batch) const;
  void report(const std::string& kind, const std::string& message);
  void sendReports() noexcept;
  void handleEncoded(const void* data, std::size_t size, const std::string& channel);

  Buffer& buffer_;
  ListenerOptions options_;
  std::unique_ptr<lcm::LCM> owned_lcm_;
  lcm::LCM& lcm_;
  std::vector<SubscriptionBudget> queues_;  // one per channel subscribed to

  mutable std::mutex mutex_;  // guards what follows
  ListenerStatistics statistics_;
  std::unique_ptr<detail::ListenerAuthorities> authorities_;
  AuthorityStatistics forgotten_;  // summed over the senders forgotten
  bool heard_dynamic_ = false;
  std::size_t resets_reported_ = 0;
  std::map<std::string, bool> reported_;
  std::vector<std::string> unsent_reports_;  // one per kind reported at most, and 10 resets

  // What handling a message decodes into, kept from one message to the next so that a stream
  // of batches reuses its strings and arrays; taken by one call at a time (ScratchLease).
  std::unique_ptr<Scratch> scratch_;
  std::atomic<bool> scratch_taken_{false};

  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace lcmtf
