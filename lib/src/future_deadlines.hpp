#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

namespace lcmtf::detail {

/// Deadlines for pending futures, kept by one thread that starts with the first deadline.
/// Each entry ends exactly once: claimed by whoever settles it first, or expired by the thread.
class FutureDeadlines {
 public:
  /// Called at expiry with an empty reason, or at stop() with the reason given there.
  using Expire = std::function<void(const std::string& reason)>;

  FutureDeadlines() = default;
  ~FutureDeadlines();
  FutureDeadlines(const FutureDeadlines&) = delete;
  FutureDeadlines& operator=(const FutureDeadlines&) = delete;

  std::uint64_t add(std::chrono::steady_clock::time_point deadline, Expire expire);
  /// Something to undo when the entry expires (cancelling the request it waits on).
  void attachCancel(std::uint64_t ticket, std::function<void()> cancel);
  /// True for the one caller that takes the entry; false when it has already ended.
  bool claim(std::uint64_t ticket);
  /// Ends every entry with `reason` and stops the thread.
  void stop(const std::string& reason);

 private:
  struct Entry {
    std::chrono::steady_clock::time_point deadline;
    Expire expire;
    std::function<void()> cancel;
  };
  void run();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::uint64_t, Entry> entries_;
  std::uint64_t next_ticket_ = 1;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace lcmtf::detail
