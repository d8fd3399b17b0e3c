// The C++ half of bench/python_lookup_bench.py: writes buffer_core_bench's PR2-scale workload as
// JSON on stdout (frames, each edge with its samples, the queries), so that the Python side
// fills its buffers with exactly this tree, together with the nanoseconds the same lookups by
// frame name take here, in C++.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "lcmtf_subject.hpp"
#include "tree_shapes.hpp"

namespace {

using bench::Query;
using bench::Workload;

constexpr int kRounds = 7;
constexpr int kPasses = 25;  // over the 4096 queries in each round

// The best of kRounds of kPasses over `queries`, in nanoseconds a lookup.
template <class Lookup>
double nanosecondsPerLookup(const std::vector<Query>& queries, Lookup lookup) {
  double best = 1e300;
  double sink = 0;
  for (int round = 0; round < kRounds; ++round) {
    const auto start = std::chrono::steady_clock::now();
    for (int pass = 0; pass < kPasses; ++pass) {
      for (const Query& q : queries) sink += lookup(q);
    }
    const std::chrono::duration<double, std::nano> took = std::chrono::steady_clock::now() - start;
    best = std::min(best, took.count() / static_cast<double>(kPasses * queries.size()));
  }
  if (sink == 0.123456789) std::puts("");  // keeps the lookups from being optimized away
  return best;
}

void printQueries(const char* name, const std::vector<Query>& queries) {
  std::printf("\"%s\": [", name);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    std::printf("%s[%zu, %zu, %lld, %lld, %zu]", i == 0 ? "" : ", ", q.target, q.source,
                static_cast<long long>(q.time), static_cast<long long>(q.other_time), q.fixed);
  }
  std::printf("]");
}

void printWorkload(const Workload& w) {
  std::printf("{\"frames\": [");
  for (std::size_t i = 0; i < w.names.size(); ++i) {
    std::printf("%s\"%s\"", i == 0 ? "" : ", ", w.names[i].c_str());
  }
  std::printf("],\n\"static_utime\": %lld,\n\"edges\": [\n",
              static_cast<long long>(w.oldest_common));
  for (std::size_t e = 0; e < w.edges.size(); ++e) {
    const bench::Edge& edge = w.edges[e];
    std::printf(
        "{\"parent\": %zu, \"child\": %zu, \"dynamic\": %s, \"first_utime\": %lld, "
        "\"period\": %lld, \"samples\": [",
        edge.parent, edge.child, edge.dynamic ? "true" : "false",
        static_cast<long long>(edge.first_stamp), static_cast<long long>(Workload::kPeriod));
    for (std::size_t k = 0; k < edge.samples.size(); ++k) {
      const bench::Pose& p = edge.samples[k];
      std::printf("%s[%.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g]", k == 0 ? "" : ", ", p.x,
                  p.y, p.z, p.qx, p.qy, p.qz, p.qw);
    }
    std::printf("]}%s\n", e + 1 == w.edges.size() ? "" : ",");
  }
  std::printf("],\n");
  printQueries("random_pairs", w.random_pairs);
  std::printf(",\n");
  printQueries("deepest_chain", w.deepest_chain);
  std::printf(",\n");
}

}  // namespace

int main() {
  const Workload w = bench::makePr2Workload();
  bench::LcmtfSubject subject(w);
  bench::fill(subject, w);
  const auto x = [](const lcmtf::TransformStamped& t) { return t.transform.translation.x(); };
  const double random =
      nanosecondsPerLookup(w.random_pairs, [&](const Query& q) { return x(subject.lookup(q)); });
  const double latest = nanosecondsPerLookup(
      w.random_pairs, [&](const Query& q) { return x(subject.lookupLatest(q)); });
  const double deepest =
      nanosecondsPerLookup(w.deepest_chain, [&](const Query& q) { return x(subject.lookup(q)); });
  const double time_travel = nanosecondsPerLookup(
      w.random_pairs, [&](const Query& q) { return x(subject.lookupTimeTravel(q)); });
  printWorkload(w);
  std::printf(
      "\"cpp_ns\": {\"lookup_random\": %.1f, \"lookup_latest\": %.1f, "
      "\"lookup_deepest\": %.1f, \"lookup_time_travel\": %.1f}}\n",
      random, latest, deepest, time_travel);
  return 0;
}
