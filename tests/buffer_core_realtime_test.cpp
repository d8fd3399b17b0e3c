// A real-time thread and an ordinary one sharing a buffer on one core: neither may starve the
// other by spinning while it waits (bench/realtime_bench prints the figures).
#include <gtest/gtest.h>

#include <chrono>

#include "realtime_workload.hpp"

namespace {

using lcmtf_bench::RealtimeThread;

// Far above a lookup's microseconds and a loaded machine's scheduling delays, far below the
// near-second stalls of a waiter spinning until the kernel throttles real-time threads.
constexpr auto kStall = std::chrono::milliseconds(250);

void expectNeitherStarves(RealtimeThread realtime) {
  const lcmtf_bench::RealtimeResult result =
      lcmtf_bench::runRealtimeWorkload(realtime, std::chrono::seconds(2));
  if (!result.permitted) GTEST_SKIP() << "cannot run the real-time set-up here: " << result.why_not;
  EXPECT_LT(result.worst_lookup, kStall) << "a lookup stalled";
  // Most batches, even on a loaded machine; a receiver starved by a spinning waiter stores a
  // tenth of them.
  EXPECT_GE(result.batches_stored, result.batches_due / 2)
      << "the receiver stored only " << result.batches_stored << " of " << result.batches_due
      << " batches";
  EXPECT_GT(result.lookups, 0u);
}

TEST(BufferCoreRealtime, RealtimeLookupsBesideAnOrdinaryReceiverOnOneCore) {
  expectNeitherStarves(RealtimeThread::kLookups);
}

TEST(BufferCoreRealtime, RealtimeReceiverBesideOrdinaryLookupsOnOneCore) {
  expectNeitherStarves(RealtimeThread::kReceiver);
}

}  // namespace
