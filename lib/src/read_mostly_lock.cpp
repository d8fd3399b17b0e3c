#include "read_mostly_lock.hpp"

#include <linux/futex.h>
#include <pthread.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>

namespace lcmtf::detail {

namespace {

// Long enough to cover a write (a batch of inserts) or a read on another core without a trip
// through the kernel, which costs a sleeping reader tens of microseconds; short enough that a
// waiter on the same core as the thread it waits for wastes little before it sleeps.
constexpr auto kLongestSpin = std::chrono::microseconds(30);

void pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// Spins until `done()` or kLongestSpin has passed; whether `done()`. After a few pauses it
// yields too, which hands the core to an ordinary thread it waits for on the same core (a
// real-time thread's yield does not, and it soon sleeps instead). The clock is read only once
// the pauses are over: most waits end before, and a writer checks slots, most of them empty, on
// each lock().
template <class Done>
bool spinUntil(Done done) {
  constexpr unsigned kPausesBeforeYielding = 64;
  for (unsigned spin = 1; spin < kPausesBeforeYielding; ++spin) {
    if (done()) return true;
    pause();
  }
  const auto give_up = std::chrono::steady_clock::now() + kLongestSpin;
  for (;;) {
    if (done()) return true;
    if (std::chrono::steady_clock::now() > give_up) return false;
    sched_yield();
  }
}

// Sleeps while `word` still holds `expected` (or until woken).
void sleepWhileEquals(const std::atomic<std::uint32_t>& word, std::uint32_t expected) {
  syscall(SYS_futex, reinterpret_cast<const std::uint32_t*>(&word), FUTEX_WAIT_PRIVATE, expected,
          nullptr, nullptr, 0);
}

void wakeOne(const std::atomic<std::uint32_t>& word) {
  syscall(SYS_futex, reinterpret_cast<const std::uint32_t*>(&word), FUTEX_WAKE_PRIVATE, 1, nullptr,
          nullptr, 0);
}

// Each thread's slot, handed out in turn. The thread-local takes the general dynamic model,
// not initial-exec, so the library can be loaded by dlopen (as a Python extension is).
constexpr std::size_t kNoSlot = static_cast<std::size_t>(-1);
thread_local std::size_t thread_slot = kNoSlot;
// How many threads have taken a slot, so that a writer in a process with few threads checks
// only the slots they use. A thread counts itself before it first enters a slot, both in the
// total order of seq_cst operations that lock() reads this in.
std::atomic<std::size_t> threads_with_slots{0};

std::size_t threadSlot() {
  if (thread_slot == kNoSlot) {
    thread_slot = threads_with_slots.fetch_add(1, std::memory_order_seq_cst);
  }
  return thread_slot;
}

}  // namespace

ReadMostlyLock::ReadMostlyLock() {
  pthread_mutexattr_t attributes;
  pthread_mutexattr_init(&attributes);
  // Where the system has no priority inheritance, an ordinary mutex still never spins.
  pthread_mutexattr_setprotocol(&attributes, PTHREAD_PRIO_INHERIT);
  if (pthread_mutex_init(&writers_, &attributes) != 0) pthread_mutex_init(&writers_, nullptr);
  pthread_mutexattr_destroy(&attributes);
}

ReadMostlyLock::~ReadMostlyLock() { pthread_mutex_destroy(&writers_); }

ReadMostlyLock::Slot& ReadMostlyLock::mySlot() const { return slots_[threadSlot() % kSlots]; }

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
    wakeOne(reader_left_);
  }
}

void ReadMostlyLock::waitWhileWriting() const {
  if (spinUntil([this] { return writing_.load(std::memory_order_acquire) == 0; })) return;
  while (writing_.load(std::memory_order_seq_cst) != 0) {
    pthread_mutex_lock(&writers_);
    pthread_mutex_unlock(&writers_);
  }
}

void ReadMostlyLock::lock() {
  pthread_mutex_lock(&writers_);
  writing_.store(1, std::memory_order_seq_cst);
  const std::size_t used = std::min(kSlots, threads_with_slots.load(std::memory_order_seq_cst));
  for (std::size_t i = 0; i < used; ++i) waitUntilEmpty(slots_[i]);
}

void ReadMostlyLock::waitUntilEmpty(const Slot& slot) {
  if (spinUntil([&slot] { return slot.readers.load(std::memory_order_seq_cst) == 0; })) return;
  while (slot.readers.load(std::memory_order_seq_cst) != 0) {
    const std::uint32_t seen = reader_left_.load(std::memory_order_seq_cst);
    writer_sleeping_.store(1, std::memory_order_seq_cst);
    if (slot.readers.load(std::memory_order_seq_cst) != 0) sleepWhileEquals(reader_left_, seen);
    writer_sleeping_.store(0, std::memory_order_seq_cst);
  }
}

void ReadMostlyLock::unlock() {
  writing_.store(0, std::memory_order_seq_cst);
  pthread_mutex_unlock(&writers_);
}

}  // namespace lcmtf::detail
