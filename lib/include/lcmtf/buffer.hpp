#pragma once

#include <future>
#include <memory>
#include <string>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/do_transform.hpp"

namespace lcmtf {

/// A BufferCore whose lookups can wait for data: each waiting call wakes the moment an insert
/// makes its answer available, and gives up with TimeoutException when `timeout` runs out.
class Buffer : public BufferCore {
 public:
  explicit Buffer(Duration cache_time = kDefaultCacheTime);
  /// Pending waitForTransform futures end with TimeoutException("buffer destroyed").
  ~Buffer();

  using BufferCore::canTransform;
  using BufferCore::lookupTransform;

  /// lookupTransform that first waits up to `timeout` for the transform to become available
  /// (a zero timeout does not wait, and throws what BufferCore::lookupTransform throws).
  TransformStamped lookupTransform(const std::string& target, const std::string& source,
                                   TimePoint time, Duration timeout) const;
  TransformStamped lookupTransform(const std::string& target, TimePoint target_time,
                                   const std::string& source, TimePoint source_time,
                                   const std::string& fixed, Duration timeout) const;

  /// canTransform that waits up to `timeout`; false (with `why`) when time runs out.
  bool canTransform(const std::string& target, const std::string& source, TimePoint time,
                    Duration timeout, std::string* why = nullptr) const;
  bool canTransform(const std::string& target, TimePoint target_time, const std::string& source,
                    TimePoint source_time, const std::string& fixed, Duration timeout,
                    std::string* why = nullptr) const;

  /// `in` expressed in `target_frame` at its own stamp, waiting up to `timeout` for the data.
  template <class T>
  Stamped<T> transform(const Stamped<T>& in, const std::string& target_frame,
                       Duration timeout = Duration::zero()) const {
    return doTransform(in, lookupTransform(target_frame, in.frame_id, in.stamp, timeout));
  }
  /// Time travel: `in` through `fixed_frame` (which must not move between the two times) into
  /// `target_frame` as it was at `target_time`.
  template <class T>
  Stamped<T> transform(const Stamped<T>& in, const std::string& target_frame, TimePoint target_time,
                       const std::string& fixed_frame, Duration timeout = Duration::zero()) const {
    return doTransform(in, lookupTransform(target_frame, target_time, in.frame_id, in.stamp,
                                           fixed_frame, timeout));
  }

  /// The transform once it is available, or the lookup's error (TimeoutException after
  /// `timeout`). The wait runs on its own thread; the future may be dropped at any time.
  std::future<TransformStamped> waitForTransform(const std::string& target,
                                                 const std::string& source, TimePoint time,
                                                 Duration timeout) const;

 private:
  enum class WaitOutcome { kAvailable, kFailed, kTimedOut };
  WaitOutcome waitUntilTransformable(const std::string& target, const std::string& source,
                                     TimePoint time,
                                     std::chrono::steady_clock::time_point deadline) const;
  [[noreturn]] void throwTimeout(const std::string& what, Duration timeout,
                                 const std::string& why) const;

  class FutureDeadlines;
  std::unique_ptr<FutureDeadlines> deadlines_;
};

}  // namespace lcmtf
