#include "lcmtf_urdf/stop_signal.hpp"

#include <signal.h>

namespace lcmtf::urdf {

namespace {

std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void requestStop(int /*signal*/) { stop_requested = true; }

}  // namespace

const std::atomic<bool>& stopOnSignals() {
  struct sigaction action {};
  action.sa_handler = requestStop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a waiting select() returns so the loop sees the flag
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  return stop_requested;
}

}  // namespace lcmtf::urdf
