#pragma once

#include <atomic>
#include <chrono>

namespace lcmtf::programs {

/// Set by the first SIGINT, SIGTERM or SIGHUP (a second one ends the process); long-running
/// tools poll it and return normally, so destructors run and the exit status is 0.
const std::atomic<bool>& installStopSignalHandlers();

/// Sleeps until `duration` has passed or `stop` is set; true when `stop` is set.
bool sleepUnlessStopped(std::chrono::milliseconds duration, const std::atomic<bool>& stop);

}  // namespace lcmtf::programs
