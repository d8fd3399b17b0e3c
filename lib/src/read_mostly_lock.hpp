#pragma once

#include <array>
#include <atomic>
#include <cstddef>

namespace lcmtf::detail {

/// A reader-writer lock for data read far more often than written. Each reader thread counts
/// itself in a slot on a cache line of its own, so readers never write memory that other
/// readers touch and scale with the number of cores; a writer raises a flag (writers take turns
/// on it), waits until every slot is empty, and has the data to itself.
class ReadMostlyLock {
 public:
  ReadMostlyLock() = default;
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

  mutable std::array<Slot, kSlots> slots_;
  alignas(64) std::atomic<bool> writing_{false};
};

}  // namespace lcmtf::detail
