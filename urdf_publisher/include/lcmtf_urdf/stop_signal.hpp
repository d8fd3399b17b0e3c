#pragma once

#include <atomic>

namespace lcmtf::urdf {

/// Makes SIGINT and SIGTERM set the returned flag instead of killing the process, so a
/// program's loop can finish cleanly; blocking calls return early with EINTR.
const std::atomic<bool>& stopOnSignals();

}  // namespace lcmtf::urdf
