#include "lcmtf/message_filter.hpp"

#include <condition_variable>
#include <optional>
#include <stdexcept>

#include "future_deadlines.hpp"

namespace lcmtf {

const char* describe(FilterDropReason reason) {
  switch (reason) {
    case FilterDropReason::kQueueFull:
      return "queue full";
    case FilterDropReason::kTimeout:
      return "timed out";
    case FilterDropReason::kTransformFailed:
      return "transform failed";
    case FilterDropReason::kCount:
      break;
  }
  return "unknown";
}

namespace {

struct Outcome {
  std::uint64_t id;
  bool ready;
  FilterDropReason reason;
  std::string why;
};

}  // namespace

class MessageFilterCore::State : public std::enable_shared_from_this<State> {
 public:
  State(Buffer& buffer_in, MessageFilterOptions options_in, MessageFilterCore& owner_in)
      : buffer(buffer_in), options(std::move(options_in)), owner(owner_in) {}

  struct Waiting {
    std::string frame;
    TimePoint stamp;
    std::vector<TransformableRequestHandle> requests;
    std::size_t missing = 0;
    std::uint64_t deadline = 0;
  };

  void track(std::uint64_t id, const std::string& frame, TimePoint stamp) {
    std::vector<Outcome> outcomes;
    {
      std::lock_guard<std::mutex> guard(mutex);
      admit(id, frame, stamp, outcomes);
      // Only a message left waiting takes a place; the oldest, never this newest, makes room.
      if (waiting.size() > options.queue_size) {
        outcomes.push_back(
            remove(waiting.begin()->first, FilterDropReason::kQueueFull,
                   "the queue of " + std::to_string(options.queue_size) + " messages was full"));
      }
    }
    deliver(outcomes);
  }

  void onRequest(TransformableRequestHandle handle, TransformableResult result) {
    std::vector<Outcome> outcomes;
    {
      std::lock_guard<std::mutex> guard(mutex);
      const auto found = by_request.find(handle);
      if (found == by_request.end()) return;
      const std::uint64_t id = found->second;
      by_request.erase(found);
      Waiting& entry = waiting.at(id);
      if (result == TransformableResult::kFailure) {
        outcomes.push_back(remove(id, FilterDropReason::kTransformFailed, whyNot(entry)));
      } else if (--entry.missing == 0) {
        outcomes.push_back(remove(id, std::nullopt, {}));
      }
    }
    deliver(outcomes);
  }

  void onTimeout(std::uint64_t id) {
    std::vector<Outcome> outcomes;
    {
      std::lock_guard<std::mutex> guard(mutex);
      const auto found = waiting.find(id);
      if (found == waiting.end()) return;
      found->second.deadline = 0;
      outcomes.push_back(remove(
          id, FilterDropReason::kTimeout,
          "not transformable within " + toString(options.timeout) + ": " + whyNot(found->second)));
    }
    deliver(outcomes);
  }

  void shutdown() {
    {
      std::unique_lock<std::mutex> lock(lifetime_mutex);
      alive = false;
      idle.wait(lock, [this] { return active == 0; });
    }
    deadlines.stop("filter destroyed");
    std::lock_guard<std::mutex> guard(mutex);
    for (auto& [handle, id] : by_request) buffer.cancelTransformableRequest(handle);
    by_request.clear();
    waiting.clear();
  }

  Buffer& buffer;
  const MessageFilterOptions options;
  MessageFilterCore& owner;
  mutable std::mutex mutex;  // guards what follows
  std::map<std::uint64_t, Waiting> waiting;
  std::map<TransformableRequestHandle, std::uint64_t> by_request;
  MessageFilterStatistics statistics;
  detail::FutureDeadlines deadlines;

 private:
  void admit(std::uint64_t id, const std::string& frame, TimePoint stamp,
             std::vector<Outcome>& outcomes) {
    Waiting& entry = waiting[id];
    entry.frame = frame;
    entry.stamp = stamp;
    entry.missing = options.target_frames.size();
    const std::weak_ptr<State> weak = weak_from_this();
    for (const std::string& target : options.target_frames) {
      TransformableRequestHandle handle = 0;
      try {
        handle = buffer.addTransformableRequest(
            [weak](TransformableRequestHandle h, const std::string&, const std::string&, TimePoint,
                   TransformableResult result) {
              if (const auto state = weak.lock()) state->onRequest(h, result);
            },
            target, frame, stamp);
      } catch (const TransformException& e) {
        outcomes.push_back(remove(id, FilterDropReason::kTransformFailed, e.what()));
        return;
      }
      if (handle == 0) {
        --entry.missing;
      } else {
        entry.requests.push_back(handle);
        by_request.emplace(handle, id);
      }
    }
    if (entry.missing == 0) {
      outcomes.push_back(remove(id, std::nullopt, {}));
      return;
    }
    if (options.timeout > Duration::zero()) {
      entry.deadline = deadlines.add(std::chrono::steady_clock::now() + options.timeout,
                                     [weak, id](const std::string& reason) {
                                       if (!reason.empty()) return;
                                       if (const auto state = weak.lock()) state->onTimeout(id);
                                     });
    }
  }

  std::string whyNot(const Waiting& entry) const {
    std::string why;
    for (const std::string& target : options.target_frames) {
      if (!buffer.canTransform(target, entry.frame, entry.stamp, &why)) return why;
    }
    return why;
  }

  // Ends the wait for `id`: passed on when `reason` is empty, dropped otherwise.
  Outcome remove(std::uint64_t id, std::optional<FilterDropReason> reason, std::string why) {
    const auto found = waiting.find(id);
    if (found != waiting.end()) {
      for (TransformableRequestHandle handle : found->second.requests) {
        if (by_request.erase(handle)) buffer.cancelTransformableRequest(handle);
      }
      if (found->second.deadline) deadlines.claim(found->second.deadline);
      waiting.erase(found);
    }
    if (reason) {
      ++statistics.dropped[static_cast<std::size_t>(*reason)];
      return {id, false, *reason, std::move(why)};
    }
    ++statistics.passed;
    return {id, true, FilterDropReason::kCount, {}};
  }

  void deliver(const std::vector<Outcome>& outcomes) {
    if (outcomes.empty()) return;
    {
      std::lock_guard<std::mutex> guard(lifetime_mutex);
      if (!alive) return;
      ++active;
    }
    for (const Outcome& outcome : outcomes) {
      if (outcome.ready) {
        owner.onReady(outcome.id);
      } else {
        owner.onDropped(outcome.id, outcome.reason, outcome.why);
      }
    }
    std::lock_guard<std::mutex> guard(lifetime_mutex);
    --active;
    idle.notify_all();
  }

  std::mutex lifetime_mutex;
  std::condition_variable idle;
  int active = 0;
  bool alive = true;
};

namespace {
MessageFilterOptions checked(MessageFilterOptions options) {
  if (options.queue_size == 0) {
    throw std::invalid_argument(
        "MessageFilter: queue_size must be at least 1; an unbounded queue is not offered");
  }
  return options;
}
}  // namespace

MessageFilterCore::MessageFilterCore(Buffer& buffer, MessageFilterOptions options)
    : state_(std::make_shared<State>(buffer, checked(std::move(options)), *this)) {}

MessageFilterCore::~MessageFilterCore() = default;

void MessageFilterCore::track(std::uint64_t id, const std::string& frame, TimePoint stamp) {
  state_->track(id, frame, stamp);
}

void MessageFilterCore::shutdown() { state_->shutdown(); }

MessageFilterStatistics MessageFilterCore::statistics() const {
  std::lock_guard<std::mutex> guard(state_->mutex);
  return state_->statistics;
}

std::size_t MessageFilterCore::pending() const {
  std::lock_guard<std::mutex> guard(state_->mutex);
  return state_->waiting.size();
}

}  // namespace lcmtf
