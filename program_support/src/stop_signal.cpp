#include "lcmtf/programs/stop_signal.hpp"

#include <signal.h>

#include <algorithm>
#include <thread>

namespace lcmtf::programs {

namespace {

std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

void requestStop(int /*signal*/) { stop_requested.store(true); }

}  // namespace

const std::atomic<bool>& installStopSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = requestStop;
  action.sa_flags = SA_RESETHAND;  // a second Ctrl-C ends a program that is slow to stop
  sigemptyset(&action.sa_mask);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal_number, &action, nullptr);
  return stop_requested;
}

bool sleepUnlessStopped(std::chrono::milliseconds duration, const std::atomic<bool>& stop) {
  using namespace std::chrono_literals;
  const auto deadline = std::chrono::steady_clock::now() + duration;
  while (!stop.load()) {
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::steady_clock::duration::zero()) return false;
    std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(left, 20ms));
  }
  return true;
}

}  // namespace lcmtf::programs
