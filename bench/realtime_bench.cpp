// The real-time set-up of bench/realtime_workload.hpp, each way round: the slowest lookup and
// the batches stored. Usage: realtime_bench [seconds per set-up, default 20]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "realtime_workload.hpp"

namespace {

int report(const char* name, lcmtf_bench::RealtimeThread realtime, int seconds) {
  const lcmtf_bench::RealtimeResult result =
      lcmtf_bench::runRealtimeWorkload(realtime, std::chrono::seconds(seconds));
  if (!result.permitted) {
    std::printf("%-40s not run: %s\n", name, result.why_not.c_str());
    return 1;
  }
  std::printf(
      "%-40s worst lookup %6.3f ms (at %6.3f s)   batches stored %llu of %llu, one "
      "every %lld us   lookups %llu\n",
      name, std::chrono::duration<double, std::milli>(result.worst_lookup).count(),
      std::chrono::duration<double>(result.worst_lookup_at).count(),
      static_cast<unsigned long long>(result.batches_stored),
      static_cast<unsigned long long>(result.batches_due),
      static_cast<long long>(result.batch_period.count()),
      static_cast<unsigned long long>(result.lookups));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const int seconds = argc > 1 ? std::atoi(argv[1]) : 20;
  if (seconds <= 0) {
    std::fprintf(stderr, "usage: realtime_bench [seconds per set-up, > 0]\n");
    return 2;
  }
  std::printf("one core; 1 kHz batches of 99 transforms; lookups 500 us busy, 500 us asleep\n");
  int failures = report("SCHED_FIFO lookups alone (floor)",
                        lcmtf_bench::RealtimeThread::kLookupsAlone, seconds);
  failures += report("SCHED_FIFO lookups, ordinary receiver", lcmtf_bench::RealtimeThread::kLookups,
                     seconds);
  failures += report("SCHED_FIFO receiver, ordinary lookups",
                     lcmtf_bench::RealtimeThread::kReceiver, seconds);
  return failures == 0 ? 0 : 1;
}
