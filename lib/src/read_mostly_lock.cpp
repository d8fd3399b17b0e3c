#include "read_mostly_lock.hpp"

#include <thread>

namespace lcmtf::detail {

namespace {
// Initial-exec: a thread-local read on every lock, which must not go through __tls_get_addr.
constexpr std::size_t kNoSlot = static_cast<std::size_t>(-1);
__attribute__((tls_model("initial-exec"))) thread_local std::size_t thread_slot = kNoSlot;

std::size_t threadSlotIndex() {
  if (thread_slot == kNoSlot) {
    static std::atomic<std::size_t> next_thread{0};
    thread_slot = next_thread.fetch_add(1, std::memory_order_relaxed);
  }
  return thread_slot;
}
}  // namespace

ReadMostlyLock::Slot& ReadMostlyLock::mySlot() const { return slots_[threadSlotIndex() % kSlots]; }

// Reader and writer each announce themselves, then look for the other, both in the single
// total order of seq_cst operations: at least one of them sees the other and backs off.
void ReadMostlyLock::lock_shared() const {
  Slot& slot = mySlot();
  for (;;) {
    slot.readers.fetch_add(1, std::memory_order_seq_cst);
    if (!writing_.load(std::memory_order_seq_cst)) return;
    slot.readers.fetch_sub(1, std::memory_order_release);
    while (writing_.load(std::memory_order_acquire)) std::this_thread::yield();
  }
}

void ReadMostlyLock::unlock_shared() const {
  mySlot().readers.fetch_sub(1, std::memory_order_release);
}

void ReadMostlyLock::lock() {
  // The flag is also what writers take turns on: sections under it are short.
  while (writing_.exchange(true, std::memory_order_seq_cst)) {
    while (writing_.load(std::memory_order_relaxed)) std::this_thread::yield();
  }
  for (Slot& slot : slots_) {
    while (slot.readers.load(std::memory_order_seq_cst) != 0) std::this_thread::yield();
  }
}

void ReadMostlyLock::unlock() { writing_.store(false, std::memory_order_release); }

}  // namespace lcmtf::detail
