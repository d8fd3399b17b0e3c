#include "read_mostly_lock.hpp"

#include <linux/futex.h>
#include <pthread.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <ctime>
#include <thread>

namespace lcmtf::detail {

namespace {

// Long enough to cover a write (a batch of inserts) or a read on another core without a trip
// through the kernel, which costs a sleeping reader tens of microseconds; short enough that a
// waiter on the same core as the thread it waits for wastes little before it sleeps.
constexpr auto kLongestSpin = std::chrono::microseconds(30);

// The longest a writer sleeps before it looks at a slot again, for a reader in a slot of its own
// that left without seeing the writer (ReadMostlyLock::leave()).
constexpr auto kLongestWriterSleep = std::chrono::milliseconds(1);

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

// Sleeps while `word` still holds `expected`, until woken or `longest` has passed.
void sleepWhileEquals(const std::atomic<std::uint32_t>& word, std::uint32_t expected,
                      std::chrono::nanoseconds longest) {
  timespec timeout{};
  timeout.tv_sec = static_cast<time_t>(longest.count() / 1'000'000'000);
  timeout.tv_nsec = static_cast<long>(longest.count() % 1'000'000'000);
  syscall(SYS_futex, reinterpret_cast<const std::uint32_t*>(&word), FUTEX_WAIT_PRIVATE, expected,
          &timeout, nullptr, 0);
}

void wakeOne(const std::atomic<std::uint32_t>& word) {
  syscall(SYS_futex, reinterpret_cast<const std::uint32_t*>(&word), FUTEX_WAKE_PRIVATE, 1, nullptr,
          nullptr, 0);
}

// What a thread brings to every lock: its slot, handed out in turn, and its kernel thread id
// for the writers' futex, both looked up once. The thread-local takes the general dynamic
// model, not initial-exec, so the library can be loaded by dlopen (as a Python extension is).
constexpr std::size_t kNoSlot = static_cast<std::size_t>(-1);
struct ThreadIdentity {
  std::size_t slot = kNoSlot;
  std::uint32_t id = 0;
};
thread_local ThreadIdentity identity;
// How many threads have taken a slot, so that a writer in a process with few threads checks
// only the slots they use. A thread counts itself before it first enters a slot, both in the
// total order of seq_cst operations that lock() reads this in.
std::atomic<std::size_t> threads_with_slots{0};

std::size_t threadSlot() {
  if (identity.slot == kNoSlot) {
    identity.slot = threads_with_slots.fetch_add(1, std::memory_order_seq_cst);
  }
  return identity.slot;
}

// A child of fork() runs as a new thread in the forking thread's place: it looks its id up
// again.
void forgetThreadId() { identity.id = 0; }
const int fork_handler_registered = pthread_atfork(nullptr, nullptr, forgetThreadId);

std::uint32_t threadId() {
  if (identity.id == 0) identity.id = static_cast<std::uint32_t>(syscall(SYS_gettid));
  return identity.id;
}

// The owner word changes hands in the kernel when there are waiters, out of the sight of the
// thread sanitizer: these tell it that whatever one owner wrote, the next may read.
#if defined(__SANITIZE_THREAD__)
extern "C" void __tsan_acquire(void* address);
extern "C" void __tsan_release(void* address);
void noteTaken(const void* word) { __tsan_acquire(const_cast<void*>(word)); }
void noteReleasing(const void* word) { __tsan_release(const_cast<void*>(word)); }
#else
void noteTaken(const void*) {}
void noteReleasing(const void*) {}
#endif

}  // namespace

ReadMostlyLock::Slot& ReadMostlyLock::mySlot() const {
  const std::size_t slot = threadSlot();
  return slots_[slot < kOwnSlots ? slot : kOwnSlots + slot % kSharedSlots];
}

// Reader and writer each announce themselves, then look for the other, both in the single
// total order of seq_cst operations: at least one of them sees the other and backs off.
// That takes the reader a read-modify-write (a plain store would not be safe unless every
// write fenced every reader's core, with membarrier(): 1.4 us a call here, too dear for a
// listener's inserts).
void ReadMostlyLock::enter(Slot& slot) const {
  for (;;) {
    slot.readers.fetch_add(1, std::memory_order_seq_cst);
    if (writing_.load(std::memory_order_seq_cst) == 0) return;
    leave(slot);
    waitWhileWriting();
  }
}

// Leaving, a reader need only publish its reads (release) before it looks for a sleeping
// writer. A thread alone in its slot does that with a plain store where a shared slot takes
// another read-modify-write: a lock instruction fewer, 1-2 % off the deepest lookups of
// buffer_core_bench on the wide tree. Only once it sees a writer does it order its store before
// its next load, so that the writer either sees it gone or is seen asleep and woken. A writer it
// did not see (its store not yet seen by the writer when it looked) finds the slot empty after at
// most kLongestWriterSleep.
void ReadMostlyLock::leave(Slot& slot) const {
  if (isOwn(slot)) {
    slot.readers.store(slot.readers.load(std::memory_order_relaxed) - 1, std::memory_order_release);
    if (writing_.load(std::memory_order_relaxed) == 0) return;
    // A read-modify-write in the single total order, where a fence would do but the thread
    // sanitizer does not follow fences.
    slot.readers.fetch_add(0, std::memory_order_seq_cst);
  } else {
    slot.readers.fetch_sub(1, std::memory_order_seq_cst);
    if (writing_.load(std::memory_order_seq_cst) == 0) return;
  }
  wakeSleepingWriter();
}

void ReadMostlyLock::wakeSleepingWriter() const {
  if (writer_sleeping_.load(std::memory_order_seq_cst) != 0) {
    reader_left_.fetch_add(1, std::memory_order_seq_cst);
    wakeOne(reader_left_);
  }
}

void ReadMostlyLock::waitWhileWriting() const {
  if (spinUntil([this] { return writing_.load(std::memory_order_acquire) == 0; })) return;
  while (writing_.load(std::memory_order_seq_cst) != 0) {
    takeOwner();
    releaseOwner();
  }
}

void ReadMostlyLock::takeOwner() const {
  std::uint32_t free = 0;
  if (!owner_.compare_exchange_strong(free, threadId(), std::memory_order_seq_cst)) {
    takeOwnerInKernel();
  }
  noteTaken(&owner_);
}

// The kernel queues the waiters by priority and lends the owner the highest one's until it
// lets go. Where it has no such futexes, the waiter sleeps a moment between tries instead.
void ReadMostlyLock::takeOwnerInKernel() const {
  for (;;) {
    if (syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&owner_), FUTEX_LOCK_PI_PRIVATE, 0,
                nullptr, nullptr, 0) == 0) {
      break;
    }
    std::uint32_t free = 0;
    if (owner_.compare_exchange_strong(free, threadId(), std::memory_order_seq_cst)) break;
    if (errno == ENOSYS) std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
}

void ReadMostlyLock::releaseOwner() const {
  noteReleasing(&owner_);
  std::uint32_t held = owner_.load(std::memory_order_relaxed);
  if ((held & FUTEX_WAITERS) != 0 ||
      !owner_.compare_exchange_strong(held, 0, std::memory_order_seq_cst)) {
    syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&owner_), FUTEX_UNLOCK_PI_PRIVATE, 0,
            nullptr, nullptr, 0);
  }
}

void ReadMostlyLock::lock() {
  takeOwner();
  writing_.store(1, std::memory_order_seq_cst);
  // Threads take slots in order, their own ones first: the slots in use are the first ones.
  const std::size_t used =
      std::min(slots_.size(), threads_with_slots.load(std::memory_order_seq_cst));
  for (std::size_t i = 0; i < used; ++i) waitUntilEmpty(slots_[i]);
}

void ReadMostlyLock::waitUntilEmpty(const Slot& slot) {
  if (spinUntil([&slot] { return slot.readers.load(std::memory_order_seq_cst) == 0; })) return;
  while (slot.readers.load(std::memory_order_seq_cst) != 0) {
    const std::uint32_t seen = reader_left_.load(std::memory_order_seq_cst);
    writer_sleeping_.store(1, std::memory_order_seq_cst);
    if (slot.readers.load(std::memory_order_seq_cst) != 0) {
      sleepWhileEquals(reader_left_, seen, kLongestWriterSleep);
    }
    writer_sleeping_.store(0, std::memory_order_seq_cst);
  }
}

// Readers that still see the flag raised only wait longer; the next writer raises it again in
// the total order, after this: a release store is enough.
void ReadMostlyLock::unlock() {
  writing_.store(0, std::memory_order_release);
  releaseOwner();
}

}  // namespace lcmtf::detail
