#include "read_mostly_lock.hpp"

#include <linux/futex.h>
#include <pthread.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <climits>

namespace lcmtf::detail {

namespace {

// Brief enough to cost nothing next to a lookup, long enough to cover a short write or read
// on another core without a trip through the kernel.
constexpr int kSpins = 100;

void pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// Sleeps while `word` still holds `expected` (or until woken).
void sleepWhileEquals(const std::atomic<std::uint32_t>& word, std::uint32_t expected) {
  syscall(SYS_futex, reinterpret_cast<const std::uint32_t*>(&word), FUTEX_WAIT_PRIVATE, expected,
          nullptr, nullptr, 0);
}

void wake(const std::atomic<std::uint32_t>& word, int count) {
  syscall(SYS_futex, reinterpret_cast<const std::uint32_t*>(&word), FUTEX_WAKE_PRIVATE, count,
          nullptr, nullptr, 0);
}

// A thread's slot from its identity, with no thread-local storage (which a library loaded by
// dlopen, as a Python extension is, may not have room for).
std::size_t slotIndex(std::size_t slots) {
  const auto self = static_cast<std::uint64_t>(pthread_self());
  return static_cast<std::size_t>((self * 0x9e3779b97f4a7c15ull) >> 32) % slots;
}

}  // namespace

ReadMostlyLock::Slot& ReadMostlyLock::mySlot() const { return slots_[slotIndex(kSlots)]; }

// Reader and writer each announce themselves, then look for the other, both in the single
// total order of seq_cst operations: at least one of them sees the other and backs off.
void ReadMostlyLock::lock_shared() const {
  Slot& slot = mySlot();
  for (;;) {
    slot.readers.fetch_add(1, std::memory_order_seq_cst);
    if (writing_.load(std::memory_order_seq_cst) == 0) return;
    leave(slot);
    waitWhileWriting();
  }
}

void ReadMostlyLock::unlock_shared() const { leave(mySlot()); }

void ReadMostlyLock::leave(Slot& slot) const {
  slot.readers.fetch_sub(1, std::memory_order_seq_cst);
  if (writing_.load(std::memory_order_seq_cst) != 0 &&
      writer_sleeping_.load(std::memory_order_seq_cst) != 0) {
    reader_left_.fetch_add(1, std::memory_order_seq_cst);
    wake(reader_left_, 1);
  }
}

void ReadMostlyLock::waitWhileWriting() const {
  for (int spin = 0; spin < kSpins; ++spin) {
    if (writing_.load(std::memory_order_acquire) == 0) return;
    pause();
  }
  while (writing_.load(std::memory_order_seq_cst) != 0) {
    readers_sleeping_.fetch_add(1, std::memory_order_seq_cst);
    const std::uint32_t seen = writer_left_.load(std::memory_order_seq_cst);
    if (writing_.load(std::memory_order_seq_cst) != 0) sleepWhileEquals(writer_left_, seen);
    readers_sleeping_.fetch_sub(1, std::memory_order_seq_cst);
  }
}

void ReadMostlyLock::lock() {
  writers_.lock();
  writing_.store(1, std::memory_order_seq_cst);
  for (const Slot& slot : slots_) waitUntilEmpty(slot);
}

void ReadMostlyLock::waitUntilEmpty(const Slot& slot) {
  for (int spin = 0; spin < kSpins; ++spin) {
    if (slot.readers.load(std::memory_order_seq_cst) == 0) return;
    pause();
  }
  while (slot.readers.load(std::memory_order_seq_cst) != 0) {
    const std::uint32_t seen = reader_left_.load(std::memory_order_seq_cst);
    writer_sleeping_.store(1, std::memory_order_seq_cst);
    if (slot.readers.load(std::memory_order_seq_cst) != 0) sleepWhileEquals(reader_left_, seen);
    writer_sleeping_.store(0, std::memory_order_seq_cst);
  }
}

void ReadMostlyLock::unlock() {
  writing_.store(0, std::memory_order_seq_cst);
  writer_left_.fetch_add(1, std::memory_order_seq_cst);
  if (readers_sleeping_.load(std::memory_order_seq_cst) != 0) wake(writer_left_, INT_MAX);
  writers_.unlock();
}

}  // namespace lcmtf::detail
