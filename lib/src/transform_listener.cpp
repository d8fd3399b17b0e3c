#include "lcmtf/transform_listener.hpp"

#include <algorithm>
#include <iostream>
#include <limits>
#include <set>
#include <stdexcept>

#include "lcmtf/frame_name.hpp"
#include "lcmtf/message_conversions.hpp"
#include "lcmtf/printable.hpp"
#include "lcmtf/sendable_names.hpp"
#include "lcmtf/subscription_budget.hpp"
#include "listener_authorities.hpp"
#include "open_lcm.hpp"
#include "time_cache.hpp"

namespace lcmtf {

namespace {

// Batches in a row, from one authority, older than the cache time behind its newest, that
// make the listener take the jump back as a restart (a log replayed again) and start afresh.
constexpr int kStaleBatchesBeforeReset = 3;

// Senders whose first reset is reported; later ones are only counted.
constexpr std::size_t kResetsReported = 10;

// Transforms a listener keeps room for between messages, in the message decoded and in the
// batch it stores.
constexpr std::size_t kLargestBatchKept = 1024;

ListenerOptions checked(ListenerOptions options) {
  if (options.max_stamp_ahead < Duration::zero()) {
    throw std::invalid_argument("TransformListener: max_stamp_ahead must not be negative; got " +
                                toString(options.max_stamp_ahead));
  }
  const std::string problem = unsendableNameProblem("authority", options.authority);
  if (!problem.empty()) throw std::invalid_argument("TransformListener: " + problem);
  return options;
}

}  // namespace

struct TransformListener::Scratch {
  tf_message_t batch;
  std::vector<TransformStamped> accepted;  // may hold more than one batch's: only grows
};

// The listener's scratch for one call, or scratch of the call's own when another call holds
// it: one on another thread, or the call whose insert ran a request's callback that calls in.
class TransformListener::ScratchLease {
 public:
  explicit ScratchLease(TransformListener& listener)
      : listener_(listener),
        shared_(!listener.scratch_taken_.exchange(true, std::memory_order_acquire)) {
    if (!shared_) own_ = std::make_unique<Scratch>();
  }
  ~ScratchLease() {
    if (!shared_) return;
    // A batch far larger than robots send (a peer may send 65,536 transforms) leaves no room
    // behind: the room kept is what the batches of a robot's publishers need.
    Scratch& scratch = *listener_.scratch_;
    if (scratch.batch.transforms.capacity() > kLargestBatchKept ||
        scratch.accepted.capacity() > kLargestBatchKept) {
      scratch = Scratch{};
    }
    listener_.scratch_taken_.store(false, std::memory_order_release);
  }
  ScratchLease(const ScratchLease&) = delete;
  ScratchLease& operator=(const ScratchLease&) = delete;

  Scratch& scratch() { return shared_ ? *listener_.scratch_ : *own_; }

 private:
  TransformListener& listener_;
  const bool shared_;
  std::unique_ptr<Scratch> own_;
};

TransformListener::TransformListener(Buffer& buffer, ListenerOptions options)
    : buffer_(buffer),
      options_(checked(std::move(options))),
      owned_lcm_(detail::openLcm(options_.lcm_url)),
      lcm_(*owned_lcm_),
      authorities_(std::make_unique<detail::ListenerAuthorities>(options_.max_authorities)),
      scratch_(std::make_unique<Scratch>()) {
  subscribe();
  thread_ = std::thread([this] {
    while (!stopping_) lcm_.handleTimeout(50);
  });
}

TransformListener::TransformListener(Buffer& buffer, lcm::LCM& lcm, ListenerOptions options)
    : buffer_(buffer),
      options_(checked(std::move(options))),
      lcm_(lcm),
      authorities_(std::make_unique<detail::ListenerAuthorities>(options_.max_authorities)),
      scratch_(std::make_unique<Scratch>()) {
  if (!lcm_.good()) throw std::runtime_error("TransformListener: the LCM given is not usable");
  subscribe();
}

TransformListener::~TransformListener() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
  for (const SubscriptionBudget& queue : queues_) lcm_.unsubscribe(queue.subscription());
}

void TransformListener::subscribe() {
  if (options_.max_interpolation_gap != Duration::zero()) {
    buffer_.setMaxInterpolationGap(options_.max_interpolation_gap);
  }
  std::vector<std::string> channels{options_.static_channel};
  if (!options_.static_only) channels.push_back(options_.channel);
  try {
    for (const std::string& channel : channels) {
      lcm::Subscription* subscription =
          lcm_.subscribe(channel, &TransformListener::onMessage, this);
      queues_.emplace_back(subscription, channel, options_.queue_bytes, options_.queue_capacity);
    }
  } catch (...) {  // an LCM of the caller's must not keep calling a listener never made
    for (const SubscriptionBudget& queue : queues_) lcm_.unsubscribe(queue.subscription());
    queues_.clear();
    throw;
  }
  if (options_.request_statics_at_start) requestStatics();
}

void TransformListener::requestStatics() {
  resend_request_t request{};
  request.utime = toUtime(now());
  request.requester = options_.authority;
  lcm_.publish(options_.static_request_channel, &request);
}

ListenerStatistics TransformListener::statistics() const {
  std::lock_guard<std::mutex> guard(mutex_);
  ListenerStatistics statistics = statistics_;
  statistics.authorities_followed = authorities_->size();
  return statistics;
}

std::vector<AuthorityStatistics> TransformListener::authorityStatistics() const {
  std::lock_guard<std::mutex> guard(mutex_);
  std::vector<AuthorityStatistics> all;
  all.reserve(authorities_->size());
  authorities_->forEach([&all](const detail::HeardAuthority& heard) {
    AuthorityStatistics statistics = heard.statistics;
    const SequenceCounts counts = heard.sequenceCounts();
    statistics.lost_batches = counts.lost;
    statistics.reordered_batches = counts.reordered;
    statistics.duplicated_batches = counts.duplicated;
    statistics.sequence_restarts = counts.restarts;
    all.push_back(std::move(statistics));
  });
  return all;
}

void TransformListener::report(const std::string& kind, const std::string& message) {
  bool& reported = reported_[kind];
  if (reported || !options_.reporter) return;
  reported = true;
  unsent_reports_.push_back(printable(message) + " (reported once; later ones are only counted)");
}

// The reporter is called without the lock: it may ask for the statistics, or wait for a
// thread (Python's GIL holder) that is asking for them.
void TransformListener::sendReports() noexcept {
  std::vector<std::string> reports;
  {
    std::lock_guard<std::mutex> guard(mutex_);
    if (unsent_reports_.empty()) return;
    reports.swap(unsent_reports_);
  }
  for (const std::string& message : reports) {
    if (stopping_.load(std::memory_order_relaxed)) return;
    try {
      options_.reporter(message);
    } catch (const std::exception& e) {
      std::cerr << "lcmtf listener: its reporter threw (" << e.what() << ") on: " << message
                << '\n';
    } catch (...) {
      std::cerr << "lcmtf listener: its reporter threw on: " << message << '\n';
    }
  }
}

void TransformListener::fitQueue(const std::string& channel, std::size_t message_size) {
  const SubscriptionBudget* shortened = fitChannel(queues_, channel, message_size);
  if (!shortened) return;
  std::lock_guard<std::mutex> guard(mutex_);
  ++statistics_.queue_shortened;
  report("queue", "a message of " + std::to_string(message_size) + " bytes on " + channel +
                      ": the listener now lets LCM queue " + std::to_string(shortened->capacity()) +
                      " messages on that channel (queue_bytes " +
                      std::to_string(options_.queue_bytes) + ")");
}

void TransformListener::onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  if (stopping_.load(std::memory_order_relaxed)) return;
  // Nothing may escape into LCM's C dispatch loop.
  try {
    fitQueue(channel, buffer->data_size);
    handleEncoded(buffer->data, buffer->data_size, channel);
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> guard(mutex_);
    ++statistics_.malformed;
    report("exception", "error while handling a message on " + channel + ": " + e.what());
  } catch (...) {
    std::lock_guard<std::mutex> guard(mutex_);
    ++statistics_.malformed;
    report("exception", "unknown error while handling a message on " + channel);
  }
  sendReports();
}

void TransformListener::handleMessage(const void* data, std::size_t size,
                                      const std::string& channel) {
  if (stopping_.load(std::memory_order_relaxed)) return;
  handleEncoded(data, size, channel);
  sendReports();
}

void TransformListener::handleEncoded(const void* data, std::size_t size,
                                      const std::string& channel) {
  ScratchLease lease(*this);
  Scratch& scratch = lease.scratch();
  const DecodeResult decoded = decodeMessage(data, size, scratch.batch, options_.limits);
  if (!decoded.ok) {
    std::lock_guard<std::mutex> guard(mutex_);
    ++statistics_.malformed;
    report("malformed", "ignored a malformed message on " + channel + ": " + decoded.error);
    return;
  }
  handleBatch(scratch.batch, channel == options_.static_channel, scratch.accepted);
}

bool TransformListener::allowed(const std::string& authority) const {
  const auto& allowed = options_.allowed_authorities;
  return allowed.empty() || std::find(allowed.begin(), allowed.end(), authority) != allowed.end();
}

std::int64_t TransformListener::newestStored(const tf_message_t& batch) const {
  std::int64_t newest = std::numeric_limits<std::int64_t>::min();
  for (const transform_t& t : batch.transforms) {
    if (!buffer_.frameExists(t.parent_frame) || !buffer_.frameExists(t.child_frame)) continue;
    try {
      newest =
          std::max(newest, toUtime(buffer_.getLatestCommonTime(t.parent_frame, t.child_frame)));
    } catch (const TransformException&) {  // no data on that edge
    }
  }
  return newest;
}

detail::HeardAuthority& TransformListener::hear(const tf_message_t& batch, bool is_static) {
  bool forgot_one = false;
  detail::HeardAuthority& sender = authorities_->hear(batch.authority, forgot_one);
  if (forgot_one) ++statistics_.authorities_forgotten;
  ++sender.statistics.batches;
  SequenceTracker& sequence = is_static ? sender.static_sequence : sender.dynamic_sequence;
  const SequenceCounts before = sequence.counts();
  sequence.observe(batch.sequence);
  const SequenceCounts& after = sequence.counts();
  // Unsigned differences wrap, so a loss taken back (the batch came late) subtracts exactly.
  statistics_.lost_batches += after.lost - before.lost;
  statistics_.reordered_batches += after.reordered - before.reordered;
  statistics_.duplicated_batches += after.duplicated - before.duplicated;
  statistics_.sequence_restarts += after.restarts - before.restarts;
  return sender;
}

std::int64_t TransformListener::newestAllowedStamp() const {
  if (options_.max_stamp_ahead == Duration::zero()) return std::numeric_limits<std::int64_t>::max();
  // The limit is not negative (checked()), so its negation cannot overflow.
  return detail::saturatingSubtract(toUtime(now()), -options_.max_stamp_ahead.count());
}

// Transforms stamped beyond `newest_allowed`, which the batch's loop refuses, leave the sender's
// newest stamp as it was.
bool TransformListener::isStale(const tf_message_t& batch, std::int64_t newest_allowed,
                                detail::HeardAuthority& sender) {
  std::int64_t batch_newest = std::numeric_limits<std::int64_t>::min();
  for (const transform_t& t : batch.transforms) {
    if (t.utime <= newest_allowed) batch_newest = std::max(batch_newest, t.utime);
  }
  if (batch_newest == std::numeric_limits<std::int64_t>::min()) return false;
  if (!sender.newest) {
    // The first sender a listener hears may feed a buffer fed before (a log replayed again
    // through a new LCM and listener): what the buffer holds on these edges counts as newest.
    sender.newest = heard_dynamic_ ? batch_newest : std::max(batch_newest, newestStored(batch));
    heard_dynamic_ = true;
  }
  const std::int64_t cache_time = buffer_.cacheTime().count();
  if (batch_newest >= detail::saturatingSubtract(*sender.newest, cache_time)) {
    sender.newest = std::max(*sender.newest, batch_newest);
    sender.stale_in_a_row = 0;
    return false;
  }
  ++sender.stale_in_a_row;
  const auto now_steady = std::chrono::steady_clock::now();
  const bool reset_lately =
      sender.last_reset && now_steady - *sender.last_reset < buffer_.cacheTime();
  if (sender.stale_in_a_row < kStaleBatchesBeforeReset || reset_lately) {
    ++statistics_.stale_batches;
    ++sender.statistics.stale_batches;
    if (sender.stale_in_a_row >= kStaleBatchesBeforeReset) {
      ++statistics_.resets_held_back;
      ++sender.statistics.resets_held_back;
    }
    return true;
  }
  sender.last_reset = now_steady;
  restartHistory(batch, batch_newest, sender);
  return false;
}

void TransformListener::restartHistory(const tf_message_t& batch, std::int64_t batch_newest,
                                       detail::HeardAuthority& sender) {
  const std::size_t cleared = buffer_.clearAuthority(batch.authority);
  sender.newest = batch_newest;
  sender.stale_in_a_row = 0;
  sender.dynamic_sequence.restart();
  sender.dynamic_sequence.observe(batch.sequence);
  ++statistics_.history_resets;
  ++sender.statistics.history_resets;
  statistics_.cleared_edges += cleared;
  sender.statistics.cleared_edges += cleared;
  if (sender.reset_reported || resets_reported_ >= kResetsReported || !options_.reporter) return;
  sender.reset_reported = true;
  ++resets_reported_;
  unsent_reports_.push_back(printable(
      "time jumped back by more than the cache time on '" + batch.authority +
      "' (restarted, or a log played again?): cleared the dynamic history of the " +
      std::to_string(cleared) + " edges it sent last; static transforms and other senders' " +
      "edges kept" +
      (resets_reported_ == kResetsReported ? " (later resets of other senders are only counted)"
                                           : "")));
}

// Counts and reports `message`, stamped beyond `newest_allowed`.
void TransformListener::refuseStampedAhead(const transform_t& message, std::int64_t newest_allowed,
                                           const std::string& authority,
                                           detail::HeardAuthority& sender) {
  ++statistics_.stamped_ahead;
  ++sender.statistics.stamped_ahead;
  const std::int64_t clock = newest_allowed - options_.max_stamp_ahead.count();
  report("stamped_ahead",
         "refused transforms stamped more than " + toString(options_.max_stamp_ahead) +
             " ahead of this machine's clock (first: '" + message.parent_frame + "' -> '" +
             message.child_frame + "' from '" + authority + "' at " +
             toString(fromUtime(message.utime)) + ", " + toString(Duration(message.utime - clock)) +
             " ahead): stored, it would make its edge refuse its publishers' samples until then. "
             "If the sender's clock is ahead of this one, synchronize the clocks or raise "
             "max_stamp_ahead (0: no limit; --max-stamp-ahead in lcmtf's programs)");
}

// Whether the frames `message` names that the buffer has not seen (nor `added`, those of the
// batch so far) fit under max_frames beside `frames`; if so, they join both.
bool TransformListener::admitNewFrames(const transform_t& message, std::size_t& frames,
                                       std::set<std::string>& added) const {
  auto isNew = [&](const std::string& name) {
    const std::string bare(canonicalFrameName(name));
    return !added.count(bare) && !buffer_.frameExists(bare);
  };
  const bool new_child = isNew(message.child_frame);
  const bool new_parent =
      message.parent_frame != message.child_frame && isNew(message.parent_frame);
  const std::size_t new_frames = std::size_t{new_child} + std::size_t{new_parent};
  if (new_frames > 0 && frames + new_frames > options_.max_frames) return false;
  frames += new_frames;
  for (const std::string* name : {&message.child_frame, &message.parent_frame}) {
    added.insert(std::string(canonicalFrameName(*name)));
  }
  return true;
}

void TransformListener::handleBatch(const tf_message_t& batch, bool is_static,
                                    std::vector<TransformStamped>& accepted) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!allowed(batch.authority)) {
    ++statistics_.unauthorized;
    report("unauthorized", "ignored transforms from '" + batch.authority +
                               "', which is not among the allowed authorities");
    return;
  }
  detail::HeardAuthority& sender = hear(batch, is_static);
  const std::int64_t newest_allowed =
      is_static ? std::numeric_limits<std::int64_t>::max() : newestAllowedStamp();
  if (!is_static && isStale(batch, newest_allowed, sender)) return;
  // Each transform adds two frames at most, so a batch that cannot reach the limit, as nearly
  // every batch of a running robot, needs no look at its names.
  std::size_t frames = buffer_.frameCount();
  const std::size_t room = options_.max_frames - std::min(frames, options_.max_frames);
  const bool may_reach_limit = batch.transforms.size() > room / 2;
  std::set<std::string> added;
  if (accepted.size() < batch.transforms.size()) accepted.resize(batch.transforms.size());
  std::size_t count = 0;
  for (const transform_t& message : batch.transforms) {
    if (message.utime > newest_allowed) {
      refuseStampedAhead(message, newest_allowed, batch.authority, sender);
      continue;
    }
    if (may_reach_limit && !admitNewFrames(message, frames, added)) {
      ++statistics_.frame_limit;
      report("frame_limit", "refused new frames beyond the limit of " +
                                std::to_string(options_.max_frames) + " (first: '" +
                                message.parent_frame + "' -> '" + message.child_frame + "' from '" +
                                batch.authority + "')");
      continue;
    }
    fromMessage(message, accepted[count++]);
  }
  // Not under the listener's lock: inserting runs the callbacks of requests it decides.
  lock.unlock();
  const std::size_t stored =
      buffer_.setTransforms(accepted.data(), count, batch.authority, is_static);
  lock.lock();
  statistics_.transforms += stored;
  statistics_.rejected_transforms += count - stored;
  ++statistics_.messages;
}

}  // namespace lcmtf
