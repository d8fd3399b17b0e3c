#pragma once

#include <unistd.h>

#include <string>

namespace lcmtf::viewer {

/// This machine's host name, or "" when it has none.
inline std::string machineName() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return {};
  return name;
}

}  // namespace lcmtf::viewer
