// What a peer that changes the tree's shape on every message does to a buffer of --frames
// frames (a 4-ary tree, a third of its edges dynamic): one thread inserts as fast as it can for
// --seconds, another looks up pairs of frames at the latest time meanwhile. Three runs: inserts
// that keep each edge's parent (a robot at work), inserts that move one leaf edge from parent to
// parent, and inserts that change the value of a static edge near the root. Each prints the
// inserts per second, the lookups per second, how many lookups took over 100 us (waiting on
// the insert thread) and the slowest.
// Usage: tree_churn_bench [--frames 10000] [--seconds 3]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "positive_flags.hpp"

namespace {

using Clock = std::chrono::steady_clock;

enum class Churn { kNone, kReparent, kStaticValue };

struct Figures {
  double inserts_per_s = 0;
  double lookups_per_s = 0;
  double slowest_lookup_us = 0;
  long long slow_lookups = 0;
};

std::string frameName(int frame) { return "frame_" + std::to_string(frame); }

lcmtf::TransformStamped edge(int parent, int child, std::int64_t utime, double x) {
  return lcmtf::TransformStamped{
      lcmtf::fromUtime(utime), frameName(parent), frameName(child),
      lcmtf::Transform(Eigen::Vector3d(x, 0.1, 0.2), Eigen::Quaterniond::Identity())};
}

Figures run(int frames, int seconds, Churn churn) {
  lcmtf::BufferCore buffer;
  const std::int64_t start_utime = 1'700'000'000'000'000;
  for (int child = 1; child < frames; ++child) {
    const bool is_static = child % 3 != 0;
    buffer.setTransform(edge((child - 1) / 4, child, start_utime, 1.0), "tree", is_static);
  }
  const int leaf = frames - 1;
  std::atomic<bool> stop{false};
  std::atomic<long long> lookups{0};
  std::atomic<long long> slowest_ns{0};
  std::atomic<long long> slow{0};
  std::thread reader([&] {
    std::vector<lcmtf::FrameHandle> handles;
    for (int frame = 0; frame < frames; ++frame)
      handles.push_back(buffer.findFrame(frameName(frame)));
    lcmtf::TransformStamped result;
    long long count = 0;
    long long slowest = 0;
    long long over_100_us = 0;
    unsigned pick = 12345;
    while (!stop.load(std::memory_order_relaxed)) {
      pick = pick * 1103515245u + 12345u;
      const int a = static_cast<int>(pick % static_cast<unsigned>(frames));
      const int b = static_cast<int>((pick >> 8) % static_cast<unsigned>(frames));
      const Clock::time_point before = Clock::now();
      try {
        buffer.lookupTransform(handles[a], handles[b], lcmtf::kLatestTime, result);
      } catch (const lcmtf::TransformException&) {
      }
      const Clock::duration took = Clock::now() - before;
      slowest = std::max<long long>(slowest, took.count());
      if (took > std::chrono::microseconds(100)) ++over_100_us;
      ++count;
    }
    lookups = count;
    slowest_ns = slowest;
    slow = over_100_us;
  });
  long long inserts = 0;
  const Clock::time_point begin = Clock::now();
  const Clock::time_point end = begin + std::chrono::seconds(seconds);
  while (Clock::now() < end) {
    for (int i = 0; i < 64; ++i, ++inserts) {
      const std::int64_t utime = start_utime + 1 + inserts;
      switch (churn) {
        case Churn::kNone:
          buffer.setTransform(edge((leaf - 1) / 4, leaf, utime, 1.0), "peer", false);
          break;
        case Churn::kReparent:
          buffer.setTransform(edge(inserts % 2 == 0 ? 1 : 2, leaf, utime, 1.0), "peer", false);
          break;
        case Churn::kStaticValue:
          buffer.setTransform(edge(0, 1, utime, 1.0 + 1e-6 * static_cast<double>(inserts % 1000)),
                              "peer", true);
          break;
      }
    }
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - begin).count();
  stop = true;
  reader.join();
  return Figures{static_cast<double>(inserts) / elapsed,
                 static_cast<double>(lookups.load()) / elapsed,
                 static_cast<double>(slowest_ns.load()) / 1e3, slow.load()};
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 10000;
  int seconds = 3;
  if (!bench::parsePositiveFlags(
          argc, argv, {{"--frames", bench::into(frames)}, {"--seconds", bench::into(seconds)}}) ||
      frames < 8) {
    std::fprintf(stderr, "usage: tree_churn_bench [--frames N >= 8] [--seconds N]\n");
    return 2;
  }
  std::printf("%d frames; one thread inserts for %d s while another looks up at the latest time\n",
              frames, seconds);
  std::printf("%-36s %12s %12s %18s %15s\n", "inserts", "inserts/s", "lookups/s",
              "lookups > 100 us", "slowest lookup");
  const std::pair<const char*, Churn> runs[] = {
      {"keeping each edge's parent", Churn::kNone},
      {"moving a leaf between two parents", Churn::kReparent},
      {"changing a static edge's value", Churn::kStaticValue}};
  for (const auto& [name, churn] : runs) {
    const Figures figures = run(frames, seconds, churn);
    std::printf("%-36s %12.0f %12.0f %18lld %12.1f us\n", name, figures.inserts_per_s,
                figures.lookups_per_s, figures.slow_lookups, figures.slowest_lookup_us);
  }
  return 0;
}
