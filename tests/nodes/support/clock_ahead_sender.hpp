#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include "lcmtf/channels.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf/transform_broadcaster.hpp"

namespace lcmtf_test {

/// A sender on `url` whose clock runs a minute ahead of this one: it broadcasts odom -> base
/// (1 m along x) as 'clock_ahead' every 20 ms, until it goes out of scope.
class ClockAheadSender {
 public:
  explicit ClockAheadSender(std::string url)
      : thread_([this, url = std::move(url)] { run(url); }) {}
  ~ClockAheadSender() {
    sending_ = false;
    thread_.join();
  }
  ClockAheadSender(const ClockAheadSender&) = delete;
  ClockAheadSender& operator=(const ClockAheadSender&) = delete;

 private:
  void run(const std::string& url) {
    lcmtf::TransformBroadcaster broadcaster(url, lcmtf::kTfChannel, "clock_ahead");
    while (sending_) {
      broadcaster.sendTransform(
          {lcmtf::now() + std::chrono::minutes(1), "odom", "base",
           lcmtf::Transform({1.0, 0.0, 0.0}, Eigen::Quaterniond::Identity())});
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

  std::atomic<bool> sending_{true};
  std::thread thread_;
};

}  // namespace lcmtf_test
