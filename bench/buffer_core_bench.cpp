// BufferCore over four tree shapes (tree_shapes.hpp), and ROS tf2's BufferCore on the same data
// when built with LCMTF_BENCH_WITH_TF2. Besides the benchmark library's flags: --rounds=N (each
// kind's alternating rounds, default 9) and --jitter-us=N (every dynamic edge's stamps off its
// 100 Hz period by up to N microseconds either way, as a publisher stamping with a clock reading
// leaves them; default 0, every stamp on its period).
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "buffer_core_summary.hpp"
#include "large_arrays.hpp"
#include "lcmtf_subject.hpp"
#include "memory_latency.hpp"
#include "tree_shapes.hpp"
#include "warm_memory.hpp"
#ifdef LCMTF_BENCH_WITH_TF2
#include "tf2_subject.hpp"
#endif

namespace bench {
namespace {

constexpr std::size_t kWriterFrames = 60;
constexpr auto kWriterPeriod = std::chrono::milliseconds(1);
constexpr auto kConcurrentWindow = std::chrono::milliseconds(400);
constexpr int kConcurrentRounds = 5;
// Many short rounds rather than a few long ones: load from elsewhere on the machine comes in
// bursts, and the more rounds there are, the likelier each library has one between them.
constexpr int kDefaultRounds = 9;
constexpr double kRoundSeconds = 0.1;

// How far each dynamic edge's stamps are off its period at most (--jitter-us), set from the
// command line before the workloads are made.
std::int64_t stamp_jitter = 0;

const std::vector<Workload>& workloads() {
  static const std::vector<Workload> all = {
      makePr2Workload(stamp_jitter), makeDeepChainWorkload(stamp_jitter),
      makeWideWorkload(stamp_jitter), makeForestWorkload(stamp_jitter)};
  return all;
}

const Workload& workload(std::size_t shape) { return workloads()[shape]; }

template <class Subject>
std::unique_ptr<Subject> makeFilled(const Workload& w) {
  auto subject = std::make_unique<Subject>(w);
  fill(*subject, w);
  subject->resolveHandles();
  return subject;
}

template <class Subject>
const Subject& sharedFilled(std::size_t shape) {
  static std::vector<std::unique_ptr<Subject>> filled(workloads().size());
  if (!filled[shape]) filled[shape] = makeFilled<Subject>(workload(shape));
  return *filled[shape];
}

// The heap's bytes in use, and the large arrays lcmtf maps outside it.
std::size_t heapInUse() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd + lcmtf::detail::mappedLargeArrayBytes();
}

// In-order inserts of the next sample of each dynamic edge in turn, so every insert also prunes
// the edge's oldest sample. The buffer and the cursor persist across runs to stay in order.
template <class Subject>
void insertBench(benchmark::State& state, std::size_t shape) {
  struct Cursor {
    std::unique_ptr<Subject> subject;
    std::vector<std::size_t> dynamic;
    std::size_t position = 0;
    std::size_t step = 0;
  };
  static std::vector<Cursor> cursors(workloads().size());
  const Workload& w = workload(shape);
  Cursor& cursor = cursors[shape];
  if (!cursor.subject) {
    cursor.subject = makeFilled<Subject>(w);
    cursor.dynamic = dynamicEdges(w);
    cursor.step = w.samples;
  }
  for (auto _ : state) {
    const std::size_t index = cursor.dynamic[cursor.position];
    const Edge& edge = w.edges[index];
    cursor.subject->set(index, w.stamp(edge, cursor.step), insertedPose(edge, cursor.step));
    if (++cursor.position == cursor.dynamic.size()) {
      cursor.position = 0;
      ++cursor.step;
    }
  }
}

// The process's page faults that the kernel could serve without reading a disk, and its time
// in the kernel, in microseconds.
struct KernelUse {
  long faults = 0;
  double kernel_us = 0;
};
KernelUse kernelUse() {
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  return {usage.ru_minflt, static_cast<double>(usage.ru_stime.tv_sec) * 1e6 +
                               static_cast<double>(usage.ru_stime.tv_usec)};
}

// The first sample of every edge into an empty buffer, each one bringing a new frame. Both
// libraries start from a heap that has given its free pages back to the system, so neither
// finds memory an earlier benchmark already paid the page faults for, and from free memory that
// has been touched once (warm_memory.hpp), so that neither pays for a first touch the other
// did not.
template <class Subject>
void addFramesBench(benchmark::State& state, std::size_t shape) {
  const Workload& w = workload(shape);
  malloc_trim(0);
  warmFreeMemory();
  Subject subject(w);
  std::size_t i = 0;
  const KernelUse before = kernelUse();
  for (auto _ : state) {
    const Edge& edge = w.edges[i];
    if (edge.dynamic) {
      subject.set(i, w.stamp(edge, 0), edge.samples[0]);
    } else {
      subject.set(i, w.oldest_common, edge.samples[0], true);
    }
    ++i;
  }
  const KernelUse after = kernelUse();
  const auto frames = static_cast<double>(i);
  state.counters["page_faults_per_frame"] =
      static_cast<double>(after.faults - before.faults) / frames;
  state.counters["kernel_ns_per_frame"] = (after.kernel_us - before.kernel_us) * 1e3 / frames;
}

template <class Subject, class Lookup>
void lookupBench(benchmark::State& state, std::size_t shape, const std::vector<Query>& queries,
                 Lookup lookup) {
  const Subject& subject = sharedFilled<Subject>(shape);
  std::size_t i = 0;
  for (auto _ : state) {
    auto result = lookup(subject, queries[i]);
    benchmark::DoNotOptimize(result);
    i = (i + 1) % Workload::kQueries;
  }
}

template <class Subject>
void memoryBench(benchmark::State& state, std::size_t shape) {
  const Workload& w = workload(shape);
  for (auto _ : state) {
    Subject subject(w);
    const std::size_t before = heapInUse();
    fill(subject, w);
    const auto bytes = static_cast<double>(heapInUse() - before);
    state.counters["bytes_per_sample"] = bytes / static_cast<double>(w.storedSamples());
    state.counters["bytes_per_frame"] = bytes / static_cast<double>(w.frameCount());
  }
}

// Readers look up random pairs at random times while a writer inserts a batch of
// kWriterFrames samples (extra leaf frames off the tree) every kWriterPeriod.
template <class Subject>
void concurrentBench(benchmark::State& state) {
  using Clock = std::chrono::steady_clock;
  const Workload& w = workload(0);
  const auto readers = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    const std::unique_ptr<Subject> subject = makeFilled<Subject>(w);
    std::vector<std::size_t> written;
    for (std::size_t i = 0; i < kWriterFrames; ++i) {
      written.push_back(subject->addEdge(w.names[i * 7 % w.frameCount()],
                                         "writer_" + std::to_string(i) + "_link"));
    }
    std::atomic<bool> stop{false};
    std::atomic<std::uint64_t> lookups{0};
    std::uint64_t batches = 0;
    std::thread writer([&] {
      auto next = Clock::now();
      while (!stop.load(std::memory_order_relaxed)) {
        const std::int64_t stamp = w.newest_common + static_cast<std::int64_t>(batches) * 1000;
        for (std::size_t i = 0; i < written.size(); ++i) {
          subject->set(written[i], stamp, w.edges[i].samples[0]);
        }
        ++batches;
        next += kWriterPeriod;
        std::this_thread::sleep_until(next);
      }
    });
    std::vector<std::thread> threads;
    const auto start = Clock::now();
    for (std::size_t r = 0; r < readers; ++r) {
      threads.emplace_back([&, r] {
        std::uint64_t done = 0;
        for (std::size_t i = r * 1024; !stop.load(std::memory_order_relaxed); ++done) {
          auto result = subject->lookup(w.random_pairs[i]);
          benchmark::DoNotOptimize(result);
          i = (i + 1) % Workload::kQueries;
        }
        lookups += done;
      });
    }
    std::this_thread::sleep_until(start + kConcurrentWindow);
    stop = true;
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (std::thread& thread : threads) thread.join();
    writer.join();
    state.SetIterationTime(seconds);
    state.counters["lookups_per_s"] = static_cast<double>(lookups.load()) / seconds;
    state.counters["writer_batches_per_s"] = static_cast<double>(batches) / seconds;
  }
}

std::string benchName(const char* library, std::size_t shape, const char* kind) {
  return std::string(library) + "/" + workload(shape).shape + "/" + kind;
}

template <class Subject, class Lookup>
void addLookup(std::size_t shape, const char* kind, const std::vector<Query>& queries,
               Lookup lookup) {
  benchmark::RegisterBenchmark(benchName(Subject::kName, shape, kind).c_str(),
                               [shape, &queries, lookup](benchmark::State& state) {
                                 lookupBench<Subject>(state, shape, queries, lookup);
                               })
      ->MinTime(kRoundSeconds);
}

// The benchmarks timed call by call, one kind at a time so that both libraries' runs of a
// kind can take turns.
enum class Timed { kInsert, kRandom, kLatest, kDeepest, kTimeTravel, kCanTransform };
constexpr Timed kTimedKinds[] = {Timed::kInsert,  Timed::kRandom,     Timed::kLatest,
                                 Timed::kDeepest, Timed::kTimeTravel, Timed::kCanTransform};

template <class Subject>
void registerTimed(std::size_t shape, Timed kind) {
  const Workload& w = workload(shape);
  switch (kind) {
    case Timed::kInsert:
      benchmark::RegisterBenchmark(
          benchName(Subject::kName, shape, "insert").c_str(),
          [shape](benchmark::State& state) { insertBench<Subject>(state, shape); })
          ->MinTime(kRoundSeconds);
      break;
    case Timed::kRandom:
      addLookup<Subject>(shape, "lookup_random", w.random_pairs,
                         [](const Subject& s, const Query& q) { return s.lookup(q); });
      break;
    case Timed::kLatest:
      addLookup<Subject>(shape, "lookup_latest", w.random_pairs,
                         [](const Subject& s, const Query& q) { return s.lookupLatest(q); });
      break;
    case Timed::kDeepest:
      addLookup<Subject>(shape, "lookup_deepest", w.deepest_chain,
                         [](const Subject& s, const Query& q) { return s.lookup(q); });
      break;
    case Timed::kTimeTravel:
      addLookup<Subject>(shape, "lookup_time_travel", w.random_pairs,
                         [](const Subject& s, const Query& q) { return s.lookupTimeTravel(q); });
      break;
    case Timed::kCanTransform:
      addLookup<Subject>(shape, "can_transform", w.random_pairs,
                         [](const Subject& s, const Query& q) { return s.canTransform(q); });
      break;
  }
}

// Ways to look up that only lcmtf has.
void registerHandleLookups(std::size_t shape) {
  const std::vector<Query>& pairs = workload(shape).random_pairs;
  addLookup<LcmtfSubject>(
      shape, "lookup_by_handle", pairs,
      [](const LcmtfSubject& s, const Query& q) { return s.lookupByHandle(q); });
  addLookup<LcmtfSubject>(shape, "lookup_by_handle_into", pairs,
                          [](const LcmtfSubject& s, const Query& q) {
                            static thread_local lcmtf::TransformStamped result;
                            s.lookupByHandleInto(q, result);
                            return result.transform.translation.x();
                          });
}

template <class Subject>
void registerMemory(std::size_t shape) {
  benchmark::RegisterBenchmark(
      benchName(Subject::kName, shape, "memory").c_str(),
      [shape](benchmark::State& state) { memoryBench<Subject>(state, shape); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
}

template <class Subject>
void registerAddFrames(std::size_t shape) {
  benchmark::RegisterBenchmark(
      benchName(Subject::kName, shape, "add_frames").c_str(),
      [shape](benchmark::State& state) { addFramesBench<Subject>(state, shape); })
      ->Iterations(static_cast<benchmark::IterationCount>(workload(shape).edges.size()));
}

// One window with one reader, then one with two.
template <class Subject>
void registerThreads() {
  benchmark::RegisterBenchmark(benchName(Subject::kName, 0, "lookups_with_writer").c_str(),
                               concurrentBench<Subject>)
      ->ArgName("readers")
      ->Arg(1)
      ->Arg(2)
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
}

void printWorkloads() {
  for (const Workload& w : workloads()) {
    double edges = 0;
    double dynamic = 0;
    for (const Query& q : w.random_pairs) {
      const auto [total, moving] = w.pathLength(q.target, q.source);
      edges += static_cast<double>(total);
      dynamic += static_cast<double>(moving);
    }
    const auto n = static_cast<double>(w.random_pairs.size());
    const auto deepest = w.pathLength(0, w.deepest);
    std::printf(
        "%-10s %6zu frames, %5zu dynamic edges at 100 Hz with %4zu samples each, the rest "
        "static; deepest frame %2zu edges below its root (%2zu dynamic); random paths %5.2f "
        "edges, %5.2f dynamic\n",
        w.shape.c_str(), w.frameCount(), w.dynamicEdgeCount(), w.samples, deepest.first,
        deepest.second, edges / n, dynamic / n);
  }
  if (stamp_jitter > 0) {
    std::printf("every dynamic edge's stamps off its period by up to %lld us either way\n",
                static_cast<long long>(stamp_jitter));
  }
  std::printf("\n");
}

#ifdef LCMTF_BENCH_WITH_TF2
// The largest difference between the two libraries' answers, as a sanity check that both run
// the same workload.
void printAgreement(std::size_t shape) {
  const Workload& w = workload(shape);
  const LcmtfSubject& ours = sharedFilled<LcmtfSubject>(shape);
  const Tf2Subject& theirs = sharedFilled<Tf2Subject>(shape);
  double translation = 0;
  double rotation = 0;
  auto compare = [&](const Pose& a, const Pose& b) {
    translation =
        std::max({translation, std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
    const double sign = a.qx * b.qx + a.qy * b.qy + a.qz * b.qz + a.qw * b.qw < 0 ? -1.0 : 1.0;
    rotation = std::max({rotation, std::abs(a.qx - sign * b.qx), std::abs(a.qy - sign * b.qy),
                         std::abs(a.qz - sign * b.qz), std::abs(a.qw - sign * b.qw)});
  };
  for (std::size_t i = 0; i < Workload::kQueries; ++i) {
    const Query& q = w.random_pairs[i];
    compare(ours.pose(ours.lookup(q)), theirs.pose(theirs.lookup(q)));
    compare(ours.pose(ours.lookupLatest(q)), theirs.pose(theirs.lookupLatest(q)));
    compare(ours.pose(ours.lookupTimeTravel(q)), theirs.pose(theirs.lookupTimeTravel(q)));
    const Query& deep = w.deepest_chain[i];
    compare(ours.pose(ours.lookup(deep)), theirs.pose(theirs.lookup(deep)));
  }
  std::printf(
      "%-10s lcmtf vs tf2 on %zu queries of each lookup kind: max difference %.2e m in "
      "translation, %.2e in quaternion coefficients\n",
      w.shape.c_str(), Workload::kQueries, translation, rotation);
}
#endif

// Takes `flag`N out of the arguments into `value`, leaving the rest to the benchmark library;
// false when N is not a whole number from `least` to `most`.
bool takeWholeNumber(int& argc, char** argv, const std::string& flag, long least, long most,
                     long& value) {
  int kept = 1;
  bool good = true;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.rfind(flag, 0) != 0) {
      argv[kept++] = argv[i];
      continue;
    }
    const std::string text = argument.substr(flag.size());
    char* end = nullptr;
    const long parsed = std::strtol(text.c_str(), &end, 10);
    good = good && !text.empty() && *end == '\0' && parsed >= least && parsed <= most;
    if (good) value = parsed;
  }
  argc = kept;
  return good;
}

}  // namespace
}  // namespace bench

int main(int argc, char** argv) {
  using namespace bench;
  // A run narrowed to some benchmarks (as when profiling one) skips the agreement check, which
  // fills every shape in both libraries.
  bool whole_run = true;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]).rfind("--benchmark_filter", 0) == 0) whole_run = false;
  }
  long rounds = kDefaultRounds;
  if (!takeWholeNumber(argc, argv, "--rounds=", 1, 100, rounds)) {
    std::fprintf(stderr, "buffer_core_bench: --rounds takes a whole number from 1 to 100\n");
    return 1;
  }
  long jitter = 0;
  constexpr long kMostJitter = Workload::kPeriod / 2 - 1;
  if (!takeWholeNumber(argc, argv, "--jitter-us=", 0, kMostJitter, jitter)) {
    std::fprintf(stderr, "buffer_core_bench: --jitter-us takes a whole number from 0 to %ld\n",
                 kMostJitter);
    return 1;
  }
  stamp_jitter = jitter;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  printWorkloads();
  std::vector<std::string> shapes;
  for (std::size_t shape = 0; shape < workloads().size(); ++shape) {
    shapes.push_back(workload(shape).shape);
#ifdef LCMTF_BENCH_WITH_TF2
    if (whole_run) printAgreement(shape);
#endif
  }
  std::printf("\n");
  // Each kind runs `rounds` times, the two libraries taking turns, and the summary takes each
  // one's fastest round: a burst of load from elsewhere on the machine then slows one round,
  // not one library. The spread over the rounds is printed beside it.
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t shape = 0; shape < workloads().size(); ++shape) {
      for (const Timed kind : kTimedKinds) {
        registerTimed<LcmtfSubject>(shape, kind);
#ifdef LCMTF_BENCH_WITH_TF2
        registerTimed<Tf2Subject>(shape, kind);
#endif
      }
      registerHandleLookups(shape);
    }
    const std::size_t forest = workloads().size() - 1;
    registerAddFrames<LcmtfSubject>(forest);
#ifdef LCMTF_BENCH_WITH_TF2
    registerAddFrames<Tf2Subject>(forest);
#endif
  }
  for (std::size_t shape = 0; shape < workloads().size(); ++shape) {
    registerMemory<LcmtfSubject>(shape);
#ifdef LCMTF_BENCH_WITH_TF2
    registerMemory<Tf2Subject>(shape);
#endif
  }
  // Likewise the windows with readers and a writer: one reader and two take turns, and the
  // summary takes each one's best window.
  for (int round = 0; round < kConcurrentRounds; ++round) {
    registerThreads<LcmtfSubject>();
#ifdef LCMTF_BENCH_WITH_TF2
    registerThreads<Tf2Subject>();
#endif
  }
  RecordingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  printSummary(reporter, shapes, memoryLatencyNs());
  benchmark::Shutdown();
  return 0;
}
