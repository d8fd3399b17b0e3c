#pragma once

namespace lcmtf::detail {

// GCC takes a function whose only effect is __builtin_prefetch for one without any, and drops
// calls to it, prefetches and all (inlined helpers included): the empty volatile asm is an
// effect it keeps.

/// Starts loading the cache line at `address`, to be read.
[[gnu::always_inline]] inline void prefetchLine(const void* address) {
  __builtin_prefetch(address);
  asm volatile("");
}

/// Starts loading the cache line at `address`, to be written.
[[gnu::always_inline]] inline void prefetchLineToWrite(const void* address) {
  __builtin_prefetch(address, 1);
  asm volatile("");
}

}  // namespace lcmtf::detail
