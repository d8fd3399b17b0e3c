#include "large_arrays.hpp"

#include <sys/mman.h>

#include <atomic>
#include <cstdint>
#include <new>

namespace lcmtf::detail {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kPage = 4096;
constexpr std::align_val_t kCacheLine{64};

std::atomic<std::size_t> mapped_bytes{0};

std::size_t roundedUp(std::size_t value, std::size_t to) { return (value + to - 1) / to * to; }

}  // namespace

void* allocateLargeArray(std::size_t bytes) {
  if (bytes < kHugePage) return ::operator new(bytes, kCacheLine);
  const std::size_t length = roundedUp(bytes, kPage);
  // Mapped a huge page longer than asked, then trimmed to start on a huge page's boundary.
  void* const mapped =
      mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  const auto first = reinterpret_cast<std::uintptr_t>(mapped);
  const std::uintptr_t start = roundedUp(first, kHugePage);
  const std::uintptr_t end = start + length;
  if (start > first) munmap(mapped, start - first);
  if (first + length + kHugePage > end)
    munmap(reinterpret_cast<void*>(end), first + length + kHugePage - end);
  // Without huge pages (not offered, or none free) the array is still usable, in small pages.
  madvise(reinterpret_cast<void*>(start), length, MADV_HUGEPAGE);
  mapped_bytes.fetch_add(length, std::memory_order_relaxed);
  return reinterpret_cast<void*>(start);
}

void freeLargeArray(void* memory, std::size_t bytes) noexcept {
  if (!memory) return;
  if (bytes < kHugePage) {
    ::operator delete(memory, kCacheLine);
    return;
  }
  const std::size_t length = roundedUp(bytes, kPage);
  munmap(memory, length);
  mapped_bytes.fetch_sub(length, std::memory_order_relaxed);
}

std::size_t mappedLargeArrayBytes() { return mapped_bytes.load(std::memory_order_relaxed); }

}  // namespace lcmtf::detail
