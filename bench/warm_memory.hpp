#pragma once

// Memory the kernel hands out that no process has touched since the machine started can cost
// far more to fault in than memory used before: a virtual machine's host backs its guest's
// memory only on first touch, microseconds a 4 KiB page. A benchmark that fills a large buffer
// then measures where in that history the machine happens to be, and transparent huge pages,
// which need whole free 2 MiB blocks, are the likeliest to land in untouched memory.

#include <sys/mman.h>

#include <cstddef>
#include <cstring>

namespace bench {

/// Touches `bytes` of fresh memory, in huge pages where the kernel gives them, and gives it
/// back: the kernel's free memory then starts with that much that has been used once, as on a
/// machine that has been running a while. Does nothing when the memory cannot be mapped.
inline void warmFreeMemory(std::size_t bytes = std::size_t{768} << 20) {
  void* memory = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (memory == MAP_FAILED) return;
  madvise(memory, bytes, MADV_HUGEPAGE);
  std::memset(memory, 1, bytes);
  munmap(memory, bytes);
}

}  // namespace bench
