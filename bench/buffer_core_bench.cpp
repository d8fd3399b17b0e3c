// BufferCore over a PR2-scale workload, and ROS tf2's BufferCore on the same data when built
// with LCMTF_BENCH_WITH_TF2.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench_summary.hpp"
#include "lcmtf_subject.hpp"
#include "pr2_workload.hpp"
#ifdef LCMTF_BENCH_WITH_TF2
#include "tf2_subject.hpp"
#endif

namespace bench {
namespace {

constexpr std::size_t kWriterFrames = 60;
constexpr auto kWriterPeriod = std::chrono::milliseconds(1);
constexpr auto kConcurrentWindow = std::chrono::milliseconds(400);
constexpr int kConcurrentRounds = 5;
constexpr int kRounds = 3;

const Workload& workload() {
  static const Workload w = makePr2Workload();
  return w;
}

template <class Subject>
std::unique_ptr<Subject> makeFilled() {
  auto subject = std::make_unique<Subject>(workload());
  fill(*subject, workload());
  return subject;
}

template <class Subject>
const Subject& sharedFilled() {
  static const std::unique_ptr<Subject> subject = makeFilled<Subject>();
  return *subject;
}

std::size_t heapInUse() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
}

// In-order inserts of the next sample of each dynamic edge in turn, so every insert also prunes
// the edge's oldest sample. The buffer and the cursor persist across runs to stay in order.
template <class Subject>
void insertBench(benchmark::State& state) {
  static const std::unique_ptr<Subject> subject = makeFilled<Subject>();
  static const std::vector<std::size_t> dynamic = dynamicEdges(workload());
  static std::size_t position = 0;
  static std::size_t step = Workload::kSamples;
  const Workload& w = workload();
  for (auto _ : state) {
    const Edge& edge = w.edges[dynamic[position]];
    subject->set(dynamic[position], w.stamp(edge, step), edge.samples[step % Workload::kSamples]);
    if (++position == dynamic.size()) {
      position = 0;
      ++step;
    }
  }
}

template <class Subject, class Lookup>
void lookupBench(benchmark::State& state, const std::vector<Query>& queries, Lookup lookup) {
  const Subject& subject = sharedFilled<Subject>();
  std::size_t i = 0;
  for (auto _ : state) {
    auto result = lookup(subject, queries[i]);
    benchmark::DoNotOptimize(result);
    i = (i + 1) % Workload::kQueries;
  }
}

template <class Subject>
void memoryBench(benchmark::State& state) {
  const Workload& w = workload();
  for (auto _ : state) {
    Subject subject(w);
    const std::size_t before = heapInUse();
    fill(subject, w);
    const std::size_t after = heapInUse();
    state.counters["bytes_per_sample"] =
        static_cast<double>(after - before) / static_cast<double>(w.storedSamples());
  }
}

// Readers look up random pairs at random times while a writer inserts a batch of
// kWriterFrames samples (extra leaf frames off the tree) every kWriterPeriod.
template <class Subject>
void concurrentBench(benchmark::State& state) {
  using Clock = std::chrono::steady_clock;
  const Workload& w = workload();
  const auto readers = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    const std::unique_ptr<Subject> subject = makeFilled<Subject>();
    std::vector<std::size_t> written;
    for (std::size_t i = 0; i < kWriterFrames; ++i) {
      written.push_back(subject->addEdge(w.names[i * 7 % Workload::kFrames],
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

template <class Subject, class Lookup>
void addLookup(const char* kind, const std::vector<Query>& queries, Lookup lookup) {
  const std::string name = std::string(Subject::kName) + "/" + kind;
  benchmark::RegisterBenchmark(name.c_str(), [&queries, lookup](benchmark::State& state) {
    lookupBench<Subject>(state, queries, lookup);
  });
}

// The benchmarks timed call by call, one kind at a time so that both libraries' runs of a
// kind can take turns.
enum class Timed { kInsert, kRandom, kLatest, kDeepest, kTimeTravel, kCanTransform };
constexpr Timed kTimedKinds[] = {Timed::kInsert,  Timed::kRandom,     Timed::kLatest,
                                 Timed::kDeepest, Timed::kTimeTravel, Timed::kCanTransform};

template <class Subject>
void registerTimed(Timed kind) {
  const Workload& w = workload();
  switch (kind) {
    case Timed::kInsert:
      benchmark::RegisterBenchmark((std::string(Subject::kName) + "/insert").c_str(),
                                   insertBench<Subject>);
      break;
    case Timed::kRandom:
      addLookup<Subject>("lookup_random", w.random_pairs,
                         [](const Subject& s, const Query& q) { return s.lookup(q); });
      break;
    case Timed::kLatest:
      addLookup<Subject>("lookup_latest", w.random_pairs,
                         [](const Subject& s, const Query& q) { return s.lookupLatest(q); });
      break;
    case Timed::kDeepest:
      addLookup<Subject>("lookup_deepest", w.deepest_chain,
                         [](const Subject& s, const Query& q) { return s.lookup(q); });
      break;
    case Timed::kTimeTravel:
      addLookup<Subject>("lookup_time_travel", w.random_pairs,
                         [](const Subject& s, const Query& q) { return s.lookupTimeTravel(q); });
      break;
    case Timed::kCanTransform:
      addLookup<Subject>("can_transform", w.random_pairs,
                         [](const Subject& s, const Query& q) { return s.canTransform(q); });
      break;
  }
}

// Ways to look up that only lcmtf has.
void registerHandleLookups() {
  addLookup<LcmtfSubject>(
      "lookup_by_handle", workload().random_pairs,
      [](const LcmtfSubject& s, const Query& q) { return s.lookupByHandle(q); });
  addLookup<LcmtfSubject>("lookup_by_handle_into", workload().random_pairs,
                          [](const LcmtfSubject& s, const Query& q) {
                            static thread_local lcmtf::TransformStamped result;
                            s.lookupByHandleInto(q, result);
                            return result.transform.translation.x();
                          });
}

template <class Subject>
void registerMemory() {
  benchmark::RegisterBenchmark((std::string(Subject::kName) + "/memory").c_str(),
                               memoryBench<Subject>)
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
}

// One window with one reader, then one with two.
template <class Subject>
void registerThreads() {
  benchmark::RegisterBenchmark((std::string(Subject::kName) + "/lookups_with_writer").c_str(),
                               concurrentBench<Subject>)
      ->ArgName("readers")
      ->Arg(1)
      ->Arg(2)
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
}

void printWorkload() {
  const Workload& w = workload();
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
      "PR2-scale workload: %zu frames, %zu dynamic edges at 100 Hz with %zu samples each, the "
      "rest static; deepest frame %zu edges from the root (%zu dynamic)\n"
      "random paths: %.2f edges on average, %.2f of them dynamic\n\n",
      w.names.size(), w.dynamicEdgeCount(), Workload::kSamples, deepest.first, deepest.second,
      edges / n, dynamic / n);
}

#ifdef LCMTF_BENCH_WITH_TF2
// The largest difference between the two libraries' answers, as a sanity check that both run
// the same workload.
void printAgreement() {
  const Workload& w = workload();
  const LcmtfSubject& ours = sharedFilled<LcmtfSubject>();
  const Tf2Subject& theirs = sharedFilled<Tf2Subject>();
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
      "lcmtf vs tf2 on %zu queries of each lookup kind: max difference %.2e m in translation, "
      "%.2e in quaternion coefficients\n\n",
      Workload::kQueries, translation, rotation);
}
#endif

}  // namespace
}  // namespace bench

int main(int argc, char** argv) {
  using namespace bench;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  printWorkload();
#ifdef LCMTF_BENCH_WITH_TF2
  printAgreement();
#endif
  // Each kind runs kRounds times, the two libraries taking turns, and the summary takes each
  // one's fastest round: a burst of load from elsewhere on the machine then slows one round,
  // not one library.
  for (int round = 0; round < kRounds; ++round) {
    for (const Timed kind : kTimedKinds) {
      registerTimed<LcmtfSubject>(kind);
#ifdef LCMTF_BENCH_WITH_TF2
      registerTimed<Tf2Subject>(kind);
#endif
    }
    registerHandleLookups();
  }
  registerMemory<LcmtfSubject>();
#ifdef LCMTF_BENCH_WITH_TF2
  registerMemory<Tf2Subject>();
#endif
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
  printSummary(reporter);
  benchmark::Shutdown();
  return 0;
}
