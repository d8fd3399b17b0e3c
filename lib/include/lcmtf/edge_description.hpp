#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "lcmtf/time.hpp"

namespace lcmtf {

/// One edge parent -> child as the buffer holds it now: who sent it and what history it has.
struct EdgeDescription {
  std::string child;
  std::string parent;     ///< of the newest sample
  std::string authority;  ///< the last sender
  bool is_static = false;
  double rate_hz = 0.0;  ///< samples per second over the history held; 0 when static
  std::size_t samples = 0;
  TimePoint oldest;  ///< stamps held; both zero for a static edge
  TimePoint newest;
  std::uint64_t authority_conflicts = 0;  ///< times another sender than the last one set it
};

}  // namespace lcmtf
