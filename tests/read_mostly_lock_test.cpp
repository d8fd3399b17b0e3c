// The buffer's reader-writer lock on its own: more reader threads than it has slots, threads
// that end while others begin, and a writer that must sleep until long readers leave. Run under
// ThreadSanitizer in CI.
#include "read_mostly_lock.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "support/test_scale.hpp"

namespace lcmtf::detail {
namespace {

using std::chrono::milliseconds;

// Two counts a writer raises together: a reader that sees them differ saw a write half done.
struct GuardedPair {
  mutable ReadMostlyLock lock;
  std::uint64_t first = 0;
  std::uint64_t second = 0;

  void write() {
    std::lock_guard<ReadMostlyLock> hold(lock);
    ++first;
    ++second;
  }
  bool readWhole() const {
    ReadMostlyLock::SharedHold hold(lock);
    return first == second;
  }
};

TEST(ReadMostlyLockConcurrency, MoreReaderThreadsThanSlotsReadOnlyWholeWrites) {
  GuardedPair pair;
  std::atomic<bool> reading{true};
  std::atomic<std::uint64_t> torn{0};
  std::atomic<std::uint64_t> reads{0};
  std::uint64_t writes = 0;
  std::thread writer([&] {
    while (reading.load()) {
      pair.write();
      ++writes;
    }
  });
  // More threads at once than there are slots, so that several count themselves in each, in
  // waves of threads that end before the next begin: the first threads in slots of their own,
  // which they leave without a read-modify-write, the rest sharing.
  constexpr int kWaves = 4;
  constexpr int kThreadsPerWave = 40;  // the lock has 16 slots of their own, 16 shared
  const int reads_per_thread = lcmtf_test::scaledCount(4000);
  for (int wave = 0; wave < kWaves; ++wave) {
    std::vector<std::thread> readers;
    for (int r = 0; r < kThreadsPerWave; ++r) {
      readers.emplace_back([&] {
        for (int i = 0; i < reads_per_thread; ++i) {
          if (!pair.readWhole()) ++torn;
          ++reads;
        }
      });
    }
    for (std::thread& reader : readers) reader.join();
  }
  reading = false;
  writer.join();
  EXPECT_EQ(torn.load(), 0u);
  EXPECT_EQ(reads.load(), static_cast<std::uint64_t>(kWaves) * kThreadsPerWave * reads_per_thread);
  EXPECT_GT(writes, 0u);
  EXPECT_TRUE(pair.readWhole());
  EXPECT_EQ(pair.first, writes);
}

// A reader holding on for far longer than a writer spins makes the writer sleep; the reader's
// leaving must wake it. A lost wake-up hangs this test.
TEST(ReadMostlyLockConcurrency, WriterSleepingOnLongReadersIsWokenWhenTheyLeave) {
  GuardedPair pair;
  const int rounds = lcmtf_test::scaledCount(200);
  constexpr int kReaders = 3;
  for (int round = 0; round < rounds; ++round) {
    std::atomic<int> holding{0};
    std::vector<std::thread> readers;
    for (int r = 0; r < kReaders; ++r) {
      readers.emplace_back([&pair, &holding, r, round] {
        ReadMostlyLock::SharedHold hold(pair.lock);
        ++holding;
        std::this_thread::sleep_for(std::chrono::microseconds(200 + 150 * ((r + round) % 4)));
      });
    }
    while (holding.load() < kReaders) std::this_thread::yield();
    pair.write();
    for (std::thread& reader : readers) reader.join();
  }
  EXPECT_EQ(pair.first, static_cast<std::uint64_t>(rounds));
  EXPECT_TRUE(pair.readWhole());
}

// A reader that comes while a writer holds the lock waits, and reads the whole write after.
TEST(ReadMostlyLockConcurrency, ReaderComingDuringAWriteWaitsForIt) {
  GuardedPair pair;
  std::atomic<bool> entered{false};
  std::uint64_t seen = 0;
  std::thread reader;
  {
    std::lock_guard<ReadMostlyLock> hold(pair.lock);
    ++pair.first;
    reader = std::thread([&] {
      ReadMostlyLock::SharedHold read(pair.lock);
      entered = true;
      seen = pair.second;
    });
    std::this_thread::sleep_for(milliseconds(20));
    EXPECT_FALSE(entered.load());
    ++pair.second;
  }
  reader.join();
  EXPECT_TRUE(entered.load());
  EXPECT_EQ(seen, 1u);
}

// Readers entering the fast way while writers come one after another, each letting readers in
// that way again first, as a reader does after a while without writers: every write ends the
// readers' bias with readers entering by the fast way, and none reads half a write. Each read
// spins between the two counts, so that a write let in among them shows.
TEST(ReadMostlyLockConcurrency, ReadersEnteringTheFastWayReadOnlyWholeWrites) {
  GuardedPair pair;
  if (!ReadMostlyLock().biasReadersNow()) {
    GTEST_SKIP() << "no fast way for readers in this build or kernel (membarrier())";
  }
  const auto spin = [](int loops) {
    for (volatile int i = 0; i < loops; ++i) {
    }
  };
  std::atomic<bool> reading{true};
  std::atomic<std::uint64_t> torn{0};
  std::atomic<std::uint64_t> biased_reads{0};
  std::vector<std::thread> readers;
  constexpr int kReaders = 2;
  for (int r = 0; r < kReaders; ++r) {
    readers.emplace_back([&] {
      // Stores that miss every cache, just before each entry: the entry's own store waits
      // behind them, long after its load of the lock's state, as long as a writer takes to come
      // in. Without the writer's barrier, about one write in a thousand tears a read here.
      std::vector<char> far(std::size_t{64} << 20);
      std::size_t at = 0;
      std::uint64_t biased = 0;
      while (reading.load(std::memory_order_relaxed)) {
        biased += pair.lock.readersBiased() ? 1 : 0;
        for (int k = 0; k < 8; ++k) {
          at = (at + 4099 * 64) % far.size();
          far[at] = static_cast<char>(k);
        }
        ReadMostlyLock::SharedHold hold(pair.lock);
        const std::uint64_t first = pair.first;
        spin(4);
        if (first != pair.second) ++torn;
      }
      biased_reads += biased;
    });
  }
  // Readers alone for a while let readers in by the fast way themselves (only readers in slots
  // of their own do: ctest runs each test in a process of its own, whose first threads have).
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!pair.lock.readersBiased() && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(milliseconds(1));
  }
  const bool biased_alone = pair.lock.readersBiased();
  // For a while rather than a number of writes: without the barrier, writes come dozens of
  // times as often, and a torn read shows within a second.
  const auto writing_until = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  std::uint64_t writes = 0;
  while (biased_alone && std::chrono::steady_clock::now() < writing_until) {
    pair.lock.biasReadersNow();
    std::lock_guard<ReadMostlyLock> hold(pair.lock);
    ++pair.first;
    spin(4);
    ++pair.second;
    ++writes;
  }
  reading = false;
  for (std::thread& reader : readers) reader.join();
  ASSERT_TRUE(biased_alone) << "readers alone never let readers in by the fast way";
  EXPECT_EQ(torn.load(), 0u);
  EXPECT_EQ(pair.first, writes);
  EXPECT_GT(biased_reads.load(), 0u);
}

}  // namespace
}  // namespace lcmtf::detail
