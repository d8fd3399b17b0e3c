#pragma once

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace bench {

/// The figure from /proc/self/status for `field` (VmRSS: now, VmHWM: the peak), in MB.
inline double processMemoryMegabytes(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field, 0) == 0) return std::atof(line.c_str() + std::strlen(field) + 1) / 1024.0;
  }
  return -1.0;
}

}  // namespace bench
