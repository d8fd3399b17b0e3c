#pragma once

#include <cstddef>

namespace lcmtf::detail {

/// Memory for a large array that lives long, as the frame table and its indexes grow into.
/// From 2 MiB up, an array is mapped on its own, aligned so that the kernel may back it with
/// transparent huge pages, and the kernel is asked to: filling a 100,000-frame tree then takes
/// one page fault per 2 MiB of it rather than one per 4 KiB (the forest's "adding a frame"
/// row). Smaller arrays come from the heap. Aligned for any type up to a cache line.
void* allocateLargeArray(std::size_t bytes);
void freeLargeArray(void* memory, std::size_t bytes) noexcept;

/// Bytes mapped by allocateLargeArray() and not yet freed: the heap's own figures leave these
/// out.
std::size_t mappedLargeArrayBytes();

/// An allocator for containers of large arrays, by allocateLargeArray().
template <class T>
struct LargeArrayAllocator {
  static_assert(alignof(T) <= 64);
  using value_type = T;

  LargeArrayAllocator() = default;
  template <class U>
  explicit LargeArrayAllocator(const LargeArrayAllocator<U>&) {}

  T* allocate(std::size_t count) { return static_cast<T*>(allocateLargeArray(count * sizeof(T))); }
  void deallocate(T* memory, std::size_t count) noexcept {
    freeLargeArray(memory, count * sizeof(T));
  }
  friend bool operator==(const LargeArrayAllocator&, const LargeArrayAllocator&) { return true; }
  friend bool operator!=(const LargeArrayAllocator&, const LargeArrayAllocator&) { return false; }
};

}  // namespace lcmtf::detail
