#pragma once

#include <atomic>
#include <chrono>

namespace lcmtf::nodes {

/// Set once SIGINT, SIGTERM or SIGHUP arrives, after installStopSignalHandlers(); long-running
/// tools poll it and return normally, so destructors run and exit status is 0.
const std::atomic<bool>& installStopSignalHandlers();

/// Sleeps until `duration` has passed or `stop` is set; true when `stop` is set.
bool sleepUnlessStopped(std::chrono::milliseconds duration, const std::atomic<bool>& stop);

}  // namespace lcmtf::nodes
