#include "read_mostly_lock.hpp"

#include <linux/futex.h>
#include <linux/membarrier.h>
#include <pthread.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
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

// The thread sanitizer follows no barrier made by the kernel: built for it, readers always enter
// the slow way, which it follows.
#if defined(__SANITIZE_THREAD__)
constexpr bool kFastReadersBuilt = false;
#else
constexpr bool kFastReadersBuilt = true;
#endif

// How many times in a row a reader enters the slow way with no writer in between before it
// lets readers enter the fast way: enough that the read-modify-writes the fast way saves (up to
// 5 ns each here) outweigh the next writer's heavyBarrier(), which takes 1 us on a machine whose
// other cores idle and 50 us (the median; 100 us at the 99th percentile) on this virtual one
// when they are busy. A buffer that lookups use between inserts, as a listener's does, keeps the
// slow way; one read on its own for a while (a static tree, a log being looked through) takes
// the fast way after a few milliseconds.
constexpr std::uint32_t kQuietReadsBeforeBias = 32768;

bool registerHeavyBarrier() {
  return syscall(SYS_membarrier, MEMBARRIER_CMD_REGISTER_PRIVATE_EXPEDITED, 0, 0) == 0;
}

// Whether the kernel makes heavyBarrier()s for this process (Linux 4.14 on, unless a sandbox
// forbids it): registered once.
bool heavyBarrierAvailable() {
  static const bool available = registerHeavyBarrier();
  return available;
}

// A full barrier on every core that runs a thread of this process: a reader's store before it
// is seen after it, and a reader's load after it sees what was stored before. A child of fork()
// registers again.
void heavyBarrier() {
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (syscall(SYS_membarrier, MEMBARRIER_CMD_PRIVATE_EXPEDITED, 0, 0) == 0) return;
    registerHeavyBarrier();
  }
  // Readers already inside by the fast way cannot be seen: going on would let the write tear
  // their reads.
  std::fputs("lcmtf: membarrier() failed where it had worked; cannot exclude readers\n", stderr);
  std::abort();
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

// Reader and writer each announce themselves, then look for the other: at least one of them
// sees the other and backs off. The slow way, both in the single total order of seq_cst
// operations, takes the reader a read-modify-write. The fast way (enterFast()) leaves the
// ordering to the writer's heavyBarrier(), too dear for every write (a listener inserts
// thousands of batches a second): readers enter it only once they have seen no writer for a
// while. 8 % off wide's deepest lookups in buffer_core_bench (60.1 -> 55.4 ns), the other rows
// the same.
void ReadMostlyLock::enter(Slot& slot) const {
  const bool own = isOwn(slot);
  if (own && enterFast(slot)) return;
  for (;;) {
    slot.readers.fetch_add(1, std::memory_order_seq_cst);
    const std::uint32_t state = state_.load(std::memory_order_seq_cst);
    if ((state & kWriting) == 0) {
      if (own) noteQuietRead(slot, state);
      return;
    }
    leave(slot);
    waitWhileWriting();
  }
}

// False, with the slot as it was, when readers are not biased or a writer has come.
bool ReadMostlyLock::enterFast(Slot& slot) const {
  const std::uint32_t seen = state_.load(std::memory_order_relaxed);
  if ((seen & (kReadersBiased | kWriting)) != kReadersBiased) return false;
  slot.readers.store(slot.readers.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  // The compiler keeps the load after the store. The processor may still load first, but a
  // writer that raises its flag, then makes a heavyBarrier(), sees the store or is seen here.
  std::atomic_signal_fence(std::memory_order_seq_cst);
  if (state_.load(std::memory_order_acquire) == seen) return true;
  leave(slot);
  return false;
}

// Counts an own slot's entries the slow way under one writers' generation, and biases readers
// once there are kQuietReadsBeforeBias of them.
void ReadMostlyLock::noteQuietRead(Slot& slot, std::uint32_t state) const {
  const std::uint32_t generation = state / kGeneration;
  if (generation != slot.generation_seen) {
    slot.generation_seen = generation;
    slot.quiet_reads = 0;
    return;
  }
  if (++slot.quiet_reads < kQuietReadsBeforeBias) return;
  slot.quiet_reads = 0;
  biasReaders(state);
}

bool ReadMostlyLock::biasReaders(std::uint32_t state) const {
  // Fails, harmlessly, where a writer has come since `state`.
  return kFastReadersBuilt && heavyBarrierAvailable() && (state & kWriting) == 0 &&
         state_.compare_exchange_strong(state, state | kReadersBiased, std::memory_order_relaxed);
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
    if (!writerIn(std::memory_order_relaxed)) return;
    // A read-modify-write in the single total order, where a fence would do but the thread
    // sanitizer does not follow fences.
    slot.readers.fetch_add(0, std::memory_order_seq_cst);
  } else {
    slot.readers.fetch_sub(1, std::memory_order_seq_cst);
    if (!writerIn(std::memory_order_seq_cst)) return;
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
  if (spinUntil([this] { return !writerIn(std::memory_order_acquire); })) return;
  while (writerIn(std::memory_order_seq_cst)) {
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
  // Raises the flag, ends the readers' bias and starts a generation at once: a reader biasing
  // readers meanwhile either did so first, and this sees it, or fails.
  std::uint32_t state = state_.load(std::memory_order_relaxed);
  while (!state_.compare_exchange_weak(
      state, ((state & ~(kWriting | kReadersBiased)) + kGeneration) | kWriting,
      std::memory_order_seq_cst)) {
  }
  if ((state & kReadersBiased) != 0) heavyBarrier();
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
// the total order, after this: a release store is enough. No reader changes the state while the
// flag is up.
void ReadMostlyLock::unlock() {
  state_.store(state_.load(std::memory_order_relaxed) & ~kWriting, std::memory_order_release);
  releaseOwner();
}

}  // namespace lcmtf::detail
