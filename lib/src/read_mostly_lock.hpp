#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <pthread.h>

namespace lcmtf::detail {

/// A reader-writer lock for data read far more often than written. Each reader thread counts
/// itself in a slot on a cache line of its own, so readers never write memory that other
/// readers touch and scale with the number of cores; a writer raises a flag (writers take turns
/// on a mutex), waits until every slot is empty, and has the data to itself.
///
/// Whoever must wait spins briefly, then sleeps in the kernel until the other side wakes it:
/// a real-time thread never spins on a lower-priority one, which could then never run. A reader
/// waits for a writer on the writers' mutex, which inherits priority: the writer then runs at
/// the waiting reader's priority until it is done.
class ReadMostlyLock {
 public:
  ReadMostlyLock();
  ~ReadMostlyLock();
  ReadMostlyLock(const ReadMostlyLock&) = delete;
  ReadMostlyLock& operator=(const ReadMostlyLock&) = delete;

  void lock_shared() const;
  void unlock_shared() const;
  void lock();
  void unlock();

 private:
  static constexpr std::size_t kSlots = 16;
  struct alignas(64) Slot {
    std::atomic<std::size_t> readers{0};
  };
  Slot& mySlot() const;
  void leave(Slot& slot) const;
  void waitWhileWriting() const;
  void waitUntilEmpty(const Slot& slot);

  mutable std::array<Slot, kSlots> slots_;
  // Read by every reader: on a line of its own, written only when a writer comes and goes.
  alignas(64) std::atomic<std::uint32_t> writing_{0};
  mutable std::atomic<std::uint32_t> writer_sleeping_{0};
  // Changed, then woken, by a reader leaving while the writer sleeps on it.
  alignas(64) mutable std::atomic<std::uint32_t> reader_left_{0};
  // Held by the writer from lock() to unlock().
  mutable pthread_mutex_t writers_;
};

}  // namespace lcmtf::detail
