#pragma once

#include <cstdint>
#include <limits>

namespace lcmtf::programs {

/// a + b and a - b clamped to the int64 range: stamps from the network may be anything.
constexpr std::int64_t saturatingAdd(std::int64_t a, std::int64_t b) {
  using Limits = std::numeric_limits<std::int64_t>;
  if (b > 0 && a > Limits::max() - b) return Limits::max();
  if (b < 0 && a < Limits::min() - b) return Limits::min();
  return a + b;
}
constexpr std::int64_t saturatingSubtract(std::int64_t a, std::int64_t b) {
  using Limits = std::numeric_limits<std::int64_t>;
  if (b > 0 && a < Limits::min() + b) return Limits::min();
  if (b < 0 && a > Limits::max() + b) return Limits::max();
  return a - b;
}

}  // namespace lcmtf::programs
