#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace lcmtf::detail {

/// A reader-writer lock for data read far more often than written. Each reader thread counts
/// itself in a slot on a cache line of its own, so readers never write memory that other
/// readers touch and scale with the number of cores; a writer raises a flag (writers take turns
/// on a mutex), waits until every slot is empty, and has the data to itself. The first threads
/// to read have a slot each, which no other thread ever counts itself in; later ones share.
///
/// While no writer has come for a while, a reader in a slot of its own enters with plain loads
/// and a plain store, where it otherwise takes a read-modify-write: the next writer pays
/// instead, with one barrier on every core the process runs on (membarrier()) before it looks
/// at the slots.
///
/// Whoever must wait spins briefly, then sleeps in the kernel until the other side wakes it:
/// a real-time thread never spins on a lower-priority one, which could then never run. Writers
/// take turns on a priority-inheriting futex, and a reader waits for a writer by taking it
/// too: the writer then runs at the waiting reader's priority until it is done.
class ReadMostlyLock {
 public:
  ReadMostlyLock() = default;
  ReadMostlyLock(const ReadMostlyLock&) = delete;
  ReadMostlyLock& operator=(const ReadMostlyLock&) = delete;

  void lock();
  void unlock();

 private:
  // Slots [0, kOwnSlots) belong to one thread each, the rest are shared.
  static constexpr std::size_t kOwnSlots = 16;
  static constexpr std::size_t kSharedSlots = 16;
  struct alignas(64) Slot {
    std::atomic<std::size_t> readers{0};
    // An own slot's thread alone: the writers' generation it last entered under, and how many
    // times in a row it entered under that one without the fast way (noteQuietRead()).
    std::uint32_t generation_seen = 0;
    std::uint32_t quiet_reads = 0;
  };
  // state_: a writer holds the lock; readers in own slots may enter the fast way; the count of
  // writers so far, in the bits above.
  static constexpr std::uint32_t kWriting = 1;
  static constexpr std::uint32_t kReadersBiased = 2;
  static constexpr std::uint32_t kGeneration = 4;

 public:
  /// Whether readers in slots of their own enter the fast way, for tests.
  bool readersBiased() const {
    return (state_.load(std::memory_order_relaxed) & kReadersBiased) != 0;
  }
  /// Lets them now, for tests, as a reader does once it has seen no writer for a while; false
  /// when a writer holds the lock, or this build or the kernel has no fast way.
  bool biasReadersNow() const { return biasReaders(state_.load(std::memory_order_relaxed)); }

  /// Holds the lock shared for its lifetime, finding the thread's slot once for both ends.
  class SharedHold {
   public:
    explicit SharedHold(const ReadMostlyLock& lock) : lock_(lock), slot_(lock.mySlot()) {
      lock_.enter(slot_);
    }
    ~SharedHold() { lock_.leave(slot_); }
    SharedHold(const SharedHold&) = delete;
    SharedHold& operator=(const SharedHold&) = delete;

   private:
    const ReadMostlyLock& lock_;
    Slot& slot_;
  };

 private:
  Slot& mySlot() const;
  void enter(Slot& slot) const;
  void leave(Slot& slot) const;
  bool isOwn(const Slot& slot) const { return &slot < slots_.data() + kOwnSlots; }
  bool writerIn(std::memory_order order) const { return (state_.load(order) & kWriting) != 0; }
  bool enterFast(Slot& slot) const;
  void noteQuietRead(Slot& slot, std::uint32_t state) const;
  bool biasReaders(std::uint32_t state) const;
  void wakeSleepingWriter() const;
  void waitWhileWriting() const;
  void waitUntilEmpty(const Slot& slot);
  void takeOwner() const;
  void takeOwnerInKernel() const;
  void releaseOwner() const;

  mutable std::array<Slot, kOwnSlots + kSharedSlots> slots_;
  // Read by every reader: on a line of its own, written only when a writer comes and goes, and
  // when a reader lets readers enter the fast way again.
  alignas(64) mutable std::atomic<std::uint32_t> state_{0};
  mutable std::atomic<std::uint32_t> writer_sleeping_{0};
  // The writers' turns, held from lock() to unlock(): 0 when free, else the holder's thread id
  // (with the kernel's waiters bit while others sleep on it), as the kernel's
  // priority-inheriting futexes keep it. A waiting reader takes it too, and lets go at once.
  mutable std::atomic<std::uint32_t> owner_{0};
  // Changed, then woken, by a reader leaving while the writer sleeps on it.
  alignas(64) mutable std::atomic<std::uint32_t> reader_left_{0};
};

}  // namespace lcmtf::detail
