#pragma once

// A robot's real-time set-up on one core: a receive thread stores a batch of transforms every
// millisecond while a control thread looks up for 500 us, then sleeps for 500 us; either of
// them may run under SCHED_FIFO. Reports the slowest lookup and how many batches got stored.
// Where storing a batch takes more than a quarter of a millisecond (a sanitizer build, a slow
// machine), batches come at four times that period instead, so that the receiver's own work
// leaves the core room and only a waiter that spins could starve the other thread.
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "lcmtf/buffer_core.hpp"

namespace lcmtf_bench {

/// Which thread runs under SCHED_FIFO; kLookupsAlone has no receiver, so its slowest lookup is
/// the machine's own floor (interrupts, a virtual machine's host) with no lock to wait on.
enum class RealtimeThread { kLookups, kReceiver, kLookupsAlone };

struct RealtimeResult {
  bool permitted = true;  // false: SCHED_FIFO or pinning refused, `why_not` says why
  std::string why_not;
  std::chrono::microseconds batch_period{1000};
  std::uint64_t batches_due = 0;
  std::uint64_t batches_stored = 0;
  std::uint64_t lookups = 0;
  std::chrono::nanoseconds worst_lookup{0};
  std::chrono::nanoseconds worst_lookup_at{0};  // after the start
};

namespace realtime_detail {

using Clock = std::chrono::steady_clock;
constexpr int kFrames = 100;
// How late a batch may be stored: what a receive queue of 100 messages holds at 1 kHz.
constexpr auto kBacklog = std::chrono::milliseconds(100);

inline std::string frameName(int index) { return "frame_" + std::to_string(index); }

// Frame i hangs under frame (i - 1) / 2: a binary tree 7 levels deep, every edge dynamic.
inline std::vector<lcmtf::TransformStamped> batchAt(std::int64_t millisecond) {
  std::vector<lcmtf::TransformStamped> batch;
  batch.reserve(kFrames - 1);
  const double t = static_cast<double>(millisecond) * 1e-3;
  for (int child = 1; child < kFrames; ++child) {
    lcmtf::Transform value(
        Eigen::Vector3d(0.1 * child, std::sin(t + child), 0.5),
        Eigen::Quaterniond(Eigen::AngleAxisd(0.01 * t * child, Eigen::Vector3d::UnitZ())));
    batch.push_back(lcmtf::TransformStamped{lcmtf::fromUtime(10'000'000 + millisecond * 1000),
                                            frameName((child - 1) / 2), frameName(child), value});
  }
  return batch;
}

// Moves the calling thread to `cpu` and, when asked, to SCHED_FIFO; "" when both worked.
inline std::string placeThread(int cpu, bool realtime) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  if (const int error = pthread_setaffinity_np(pthread_self(), sizeof(set), &set)) {
    return std::string("pinning to one core refused: ") + std::strerror(error);
  }
  if (realtime) {
    sched_param param{};
    param.sched_priority = 50;
    if (const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param)) {
      return std::string("SCHED_FIFO refused: ") + std::strerror(error);
    }
  }
  return "";
}

}  // namespace realtime_detail

/// Runs the set-up for `duration` with `realtime` under SCHED_FIFO, both threads on the core
/// the caller runs on.
inline RealtimeResult runRealtimeWorkload(RealtimeThread realtime,
                                          std::chrono::milliseconds duration) {
  using namespace realtime_detail;
  RealtimeResult result;
  // A receiver that has been running for a while: every edge holds its full history.
  lcmtf::BufferCore buffer(std::chrono::seconds(2));
  std::chrono::nanoseconds slowest_of_last_batches{0};
  for (std::int64_t millisecond = -2500; millisecond <= 0; ++millisecond) {
    const std::vector<lcmtf::TransformStamped> batch = batchAt(millisecond);
    const Clock::time_point before = Clock::now();
    buffer.setTransforms(batch, "receiver");
    if (millisecond > -100) {
      slowest_of_last_batches = std::max(slowest_of_last_batches, Clock::now() - before);
    }
  }
  using std::chrono::microseconds;
  const microseconds period = std::max(
      microseconds(1000), std::chrono::duration_cast<microseconds>(4 * slowest_of_last_batches));
  result.batch_period = period;
  const int cpu = std::max(0, sched_getcpu());
  std::atomic<bool> refused{false};
  std::string receiver_problem;
  std::string lookup_problem;
  std::atomic<int> ready{0};
  const Clock::time_point start = Clock::now() + std::chrono::milliseconds(50);
  const Clock::time_point end = start + duration;

  std::thread receiver([&] {
    receiver_problem = placeThread(cpu, realtime == RealtimeThread::kReceiver);
    if (!receiver_problem.empty()) refused = true;
    ++ready;
    std::this_thread::sleep_until(start);
    std::int64_t batch = 1;
    while (!refused && realtime != RealtimeThread::kLookupsAlone) {
      const Clock::time_point due = start + batch * period;
      if (due >= end) break;
      std::this_thread::sleep_until(due);
      buffer.setTransforms(batchAt(batch * period.count() / 1000), "receiver");
      ++result.batches_stored;
      ++batch;
      // Batches more than kBacklog late are lost, as LCM drops them from a full queue.
      while (start + batch * period + kBacklog < Clock::now()) ++batch;
    }
  });
  std::thread control([&] {
    lookup_problem = placeThread(cpu, realtime != RealtimeThread::kReceiver);
    if (!lookup_problem.empty()) refused = true;
    ++ready;
    std::mt19937 random(7);
    std::uniform_int_distribution<int> frame(0, kFrames - 1);
    std::vector<lcmtf::FrameHandle> handles;
    for (int i = 0; i < kFrames; ++i) handles.push_back(buffer.resolveFrame(frameName(i)));
    lcmtf::TransformStamped out;
    std::this_thread::sleep_until(start);
    while (!refused && Clock::now() < end) {
      const Clock::time_point busy_until = Clock::now() + std::chrono::microseconds(500);
      while (Clock::now() < busy_until) {
        const Clock::time_point before = Clock::now();
        try {
          buffer.lookupTransform(handles[frame(random)], handles[frame(random)], lcmtf::kLatestTime,
                                 out);
        } catch (const lcmtf::TransformException&) {
        }
        const Clock::time_point after = Clock::now();
        if (after - before > result.worst_lookup) {
          result.worst_lookup = after - before;
          result.worst_lookup_at = before - start;
        }
        ++result.lookups;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
  });
  receiver.join();
  control.join();
  result.batches_due = realtime == RealtimeThread::kLookupsAlone
                           ? 0
                           : static_cast<std::uint64_t>(duration / period) - 1;
  if (refused) {
    result.permitted = false;
    result.why_not = !receiver_problem.empty() ? receiver_problem : lookup_problem;
  }
  return result;
}

}  // namespace lcmtf_bench
