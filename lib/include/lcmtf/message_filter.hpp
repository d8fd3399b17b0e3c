#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "lcmtf/buffer.hpp"

namespace lcmtf {

/// Why a MessageFilter let go of a message without passing it on.
enum class FilterDropReason : std::size_t {
  kQueueFull,        ///< the queue was full: the oldest message made room
  kTimeout,          ///< the transform did not become available within the timeout
  kTransformFailed,  ///< the transform can never become available (time left the cache)
  kCount
};

/// A short name for a drop reason ("queue full", ...).
const char* describe(FilterDropReason reason);

/// How a MessageFilter waits.
struct MessageFilterOptions {
  std::vector<std::string> target_frames;  ///< every one must be reachable
  /// Messages waiting at most, at least 1: the constructor throws std::invalid_argument on 0
  /// rather than wait without bound for whatever the network sends.
  std::size_t queue_size = 100;
  Duration timeout = std::chrono::seconds(1);  ///< zero: wait until the cache drops it
};

/// What a MessageFilter has done since it was made.
struct MessageFilterStatistics {
  std::uint64_t passed = 0;
  std::array<std::uint64_t, static_cast<std::size_t>(FilterDropReason::kCount)> dropped{};
  std::uint64_t droppedCount(FilterDropReason reason) const {
    return dropped[static_cast<std::size_t>(reason)];
  }
};

/// The part of MessageFilter that does not depend on the message type: it tracks messages by
/// number and says when each is ready or dropped.
class MessageFilterCore {
 public:
  MessageFilterCore(Buffer& buffer, MessageFilterOptions options);
  virtual ~MessageFilterCore();
  MessageFilterCore(const MessageFilterCore&) = delete;
  MessageFilterCore& operator=(const MessageFilterCore&) = delete;

  MessageFilterStatistics statistics() const;
  std::size_t pending() const;

 protected:
  /// Starts waiting for message `id`, which lives in `frame` at `stamp`.
  void track(std::uint64_t id, const std::string& frame, TimePoint stamp);
  /// Ends every wait; derived classes call it first in their destructor.
  void shutdown();
  virtual void onReady(std::uint64_t id) = 0;
  virtual void onDropped(std::uint64_t id, FilterDropReason reason, const std::string& why) = 0;

 private:
  class State;
  std::shared_ptr<State> state_;
};

/// Holds incoming messages until their frame can be transformed into every target frame at the
/// message's stamp, then calls `ready`; every message dropped instead goes to `dropped` with
/// the reason. Callbacks run on the thread whose insert (or timeout) decided the message.
template <class Message>
class MessageFilter : public MessageFilterCore {
 public:
  using FrameOf = std::function<std::string(const Message&)>;
  using StampOf = std::function<TimePoint(const Message&)>;
  using Ready = std::function<void(const Message&)>;
  using Dropped =
      std::function<void(const Message&, FilterDropReason reason, const std::string& why)>;

  MessageFilter(Buffer& buffer, MessageFilterOptions options, FrameOf frame_of, StampOf stamp_of,
                Ready ready, Dropped dropped = {})
      : MessageFilterCore(buffer, std::move(options)),
        frame_of_(std::move(frame_of)),
        stamp_of_(std::move(stamp_of)),
        ready_(std::move(ready)),
        dropped_(std::move(dropped)) {}
  ~MessageFilter() override { shutdown(); }

  /// Passes `message` on now if it can be transformed, leaving the queue as it is; else
  /// queues it, and when the queue is full the oldest waiting message is dropped to make room.
  void add(Message message) {
    const std::string frame = frame_of_(message);
    const TimePoint stamp = stamp_of_(message);
    std::uint64_t id = 0;
    {
      std::lock_guard<std::mutex> guard(mutex_);
      id = next_id_++;
      messages_.emplace(id, std::move(message));
    }
    track(id, frame, stamp);
  }

 private:
  Message take(std::uint64_t id) {
    std::lock_guard<std::mutex> guard(mutex_);
    auto node = messages_.extract(id);
    return std::move(node.mapped());
  }
  void onReady(std::uint64_t id) override { ready_(take(id)); }
  void onDropped(std::uint64_t id, FilterDropReason reason, const std::string& why) override {
    Message message = take(id);
    if (dropped_) dropped_(message, reason, why);
  }

  FrameOf frame_of_;
  StampOf stamp_of_;
  Ready ready_;
  Dropped dropped_;
  std::mutex mutex_;
  std::map<std::uint64_t, Message> messages_;
  std::uint64_t next_id_ = 1;
};

}  // namespace lcmtf
