#include "lcmtf/buffer.hpp"

#include <condition_variable>
#include <mutex>

#include "future_deadlines.hpp"

namespace lcmtf {

namespace {

using SteadyTime = std::chrono::steady_clock::time_point;

// Set once by a transformable request's callback; read by the thread that waits.
struct WaitState {
  std::mutex mutex;
  std::condition_variable changed;
  bool decided = false;
  TransformableResult result = TransformableResult::kFailure;
};

std::string lookupWhat(const std::string& target, const std::string& source, TimePoint time) {
  return "a transform of '" + source + "' into '" + target + "' " +
         (time == kLatestTime ? std::string("at the latest common time") : "at " + toString(time));
}

}  // namespace

class Buffer::FutureDeadlines : public detail::FutureDeadlines {};

Buffer::Buffer(Duration cache_time)
    : BufferCore(cache_time), deadlines_(std::make_unique<FutureDeadlines>()) {}

Buffer::~Buffer() { deadlines_->stop("buffer destroyed before the transform became available"); }

Buffer::WaitOutcome Buffer::waitUntilTransformable(const std::string& target,
                                                   const std::string& source, TimePoint time,
                                                   SteadyTime deadline) const {
  auto state = std::make_shared<WaitState>();
  const TransformableRequestHandle handle = addTransformableRequest(
      [state](TransformableRequestHandle, const std::string&, const std::string&, TimePoint,
              TransformableResult result) {
        std::lock_guard<std::mutex> guard(state->mutex);
        state->decided = true;
        state->result = result;
        state->changed.notify_all();
      },
      target, source, time);
  if (handle == 0) return WaitOutcome::kAvailable;
  std::unique_lock<std::mutex> lock(state->mutex);
  if (!state->changed.wait_until(lock, deadline, [&] { return state->decided; })) {
    lock.unlock();
    cancelTransformableRequest(handle);
    return BufferCore::canTransform(target, source, time) ? WaitOutcome::kAvailable
                                                          : WaitOutcome::kTimedOut;
  }
  return state->result == TransformableResult::kAvailable ? WaitOutcome::kAvailable
                                                          : WaitOutcome::kFailed;
}

void Buffer::throwTimeout(const std::string& what, Duration timeout, const std::string& why) const {
  throw TimeoutException("timed out after " + toString(timeout) + " waiting for " + what +
                         (why.empty() ? std::string() : "; still missing: " + why));
}

TransformStamped Buffer::lookupTransform(const std::string& target, const std::string& source,
                                         TimePoint time, Duration timeout) const {
  if (timeout <= Duration::zero()) return BufferCore::lookupTransform(target, source, time);
  const SteadyTime deadline = std::chrono::steady_clock::now() + timeout;
  if (waitUntilTransformable(target, source, time, deadline) == WaitOutcome::kTimedOut) {
    std::string why;
    if (!BufferCore::canTransform(target, source, time, &why)) {
      throwTimeout(lookupWhat(target, source, time), timeout, why);
    }
  }
  return BufferCore::lookupTransform(target, source, time);
}

TransformStamped Buffer::lookupTransform(const std::string& target, TimePoint target_time,
                                         const std::string& source, TimePoint source_time,
                                         const std::string& fixed, Duration timeout) const {
  if (timeout <= Duration::zero()) {
    return BufferCore::lookupTransform(target, target_time, source, source_time, fixed);
  }
  const SteadyTime deadline = std::chrono::steady_clock::now() + timeout;
  for (const auto& [to, from, time] :
       {std::tuple{fixed, source, source_time}, std::tuple{target, fixed, target_time}}) {
    if (waitUntilTransformable(to, from, time, deadline) == WaitOutcome::kTimedOut) {
      std::string why;
      if (!BufferCore::canTransform(to, from, time, &why)) {
        throwTimeout(lookupWhat(to, from, time) + " (time travel of '" + source + "' into '" +
                         target + "' through '" + fixed + "')",
                     timeout, why);
      }
    }
  }
  return BufferCore::lookupTransform(target, target_time, source, source_time, fixed);
}

bool Buffer::canTransform(const std::string& target, const std::string& source, TimePoint time,
                          Duration timeout, std::string* why) const {
  const SteadyTime deadline = std::chrono::steady_clock::now() + timeout;
  try {
    waitUntilTransformable(target, source, time, deadline);
  } catch (const TransformException& e) {
    if (why) *why = e.what();
    return false;
  }
  return BufferCore::canTransform(target, source, time, why);
}

bool Buffer::canTransform(const std::string& target, TimePoint target_time,
                          const std::string& source, TimePoint source_time,
                          const std::string& fixed, Duration timeout, std::string* why) const {
  const SteadyTime deadline = std::chrono::steady_clock::now() + timeout;
  try {
    waitUntilTransformable(fixed, source, source_time, deadline);
    waitUntilTransformable(target, fixed, target_time, deadline);
  } catch (const TransformException& e) {
    if (why) *why = e.what();
    return false;
  }
  return BufferCore::canTransform(target, target_time, source, source_time, fixed, why);
}

std::future<TransformStamped> Buffer::waitForTransform(const std::string& target,
                                                       const std::string& source, TimePoint time,
                                                       Duration timeout) const {
  auto promise = std::make_shared<std::promise<TransformStamped>>();
  std::future<TransformStamped> future = promise->get_future();
  auto settle = [this, promise, target, source, time] {
    try {
      promise->set_value(BufferCore::lookupTransform(target, source, time));
    } catch (...) {
      promise->set_exception(std::current_exception());
    }
  };
  const std::uint64_t ticket = deadlines_->add(
      std::chrono::steady_clock::now() + timeout,
      [this, promise, settle, target, source, time, timeout](const std::string& reason) {
        std::string why;
        if (reason.empty() && BufferCore::canTransform(target, source, time, &why)) {
          settle();
          return;
        }
        try {
          throwTimeout(lookupWhat(target, source, time), timeout, reason.empty() ? why : reason);
        } catch (...) {
          promise->set_exception(std::current_exception());
        }
      });
  const TransformableRequestHandle handle = addTransformableRequest(
      [this, ticket, settle](TransformableRequestHandle, const std::string&, const std::string&,
                             TimePoint, TransformableResult) {
        if (deadlines_->claim(ticket)) settle();
      },
      target, source, time);
  if (handle == 0) {
    if (deadlines_->claim(ticket)) settle();
  } else {
    deadlines_->attachCancel(ticket, [this, handle] { cancelTransformableRequest(handle); });
  }
  return future;
}

}  // namespace lcmtf
