#pragma once

// The latency of a load that misses every cache, measured by chasing pointers through a random
// cycle much larger than the caches: each load's address comes from the one before, so nothing
// overlaps. Lookups in a tree far larger than the caches pay a few of these each.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace bench {

inline double memoryLatencyNs(std::size_t bytes = std::size_t{256} << 20,
                              std::size_t loads = 4'000'000) {
  // One pointer per cache line, visited in a random order that forms a single cycle.
  constexpr std::size_t kLine = 64 / sizeof(std::size_t);
  const std::size_t lines = bytes / 64;
  std::vector<std::size_t> order(lines);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin() + 1, order.end(), std::mt19937_64(42));
  std::vector<std::size_t> next(lines * kLine);
  for (std::size_t i = 0; i < lines; ++i) {
    next[order[i] * kLine] = order[(i + 1) % lines] * kLine;
  }
  std::size_t at = 0;
  for (std::size_t i = 0; i < lines; ++i) at = next[at];  // brings the pages in
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < loads; ++i) at = next[at];
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  volatile std::size_t keep = at;
  (void)keep;
  return seconds * 1e9 / static_cast<double>(loads);
}

}  // namespace bench
