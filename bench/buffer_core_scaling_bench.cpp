// Lookup cost against the size of the tree and the length of the history, with the path
// itself fixed: 15 edges from the leaf to the root, 5 of them dynamic at 100 Hz. The cost
// should follow the path, not the tree or the history. Also the cost of adding a frame, one
// edge at a time, against the number of frames already there.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"

namespace {

constexpr int kPathEdges = 15;
constexpr std::int64_t kPeriod = 10'000;  // 100 Hz, microseconds
constexpr std::int64_t kStart = 1'700'000'000'000'000;

lcmtf::Transform wobble(double phase) {
  return lcmtf::Transform(
      Eigen::Vector3d(0.1 * std::sin(phase), 0.05 * std::cos(phase), 0.2),
      Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * std::sin(phase), Eigen::Vector3d::UnitZ())));
}

// A path of kPathEdges edges from "leaf" up to "map", every third one dynamic with `seconds` of
// history, plus enough other frames hanging off the path to make `frames` in all.
struct ScalingTree {
  ScalingTree(int frames, int seconds) : buffer(std::chrono::seconds(seconds)) {
    const std::int64_t samples = seconds * 1'000'000 / kPeriod;
    newest = kStart + (samples - 1) * kPeriod;
    std::vector<std::string> path{"map"};
    for (int i = 1; i <= kPathEdges; ++i)
      path.push_back(i == kPathEdges ? "leaf" : "link_" + std::to_string(i));
    for (int i = 1; i <= kPathEdges; ++i) {
      const bool dynamic = i % 3 == 0;
      if (!dynamic) {
        buffer.setTransform({{}, path[i - 1], path[i], wobble(i)}, "bench", true);
        continue;
      }
      for (std::int64_t k = 0; k < samples; ++k) {
        buffer.setTransform({lcmtf::fromUtime(kStart + k * kPeriod), path[i - 1], path[i],
                             wobble(0.01 * static_cast<double>(k) + i)},
                            "bench");
      }
    }
    std::mt19937 random(5);
    for (int extra = 0; extra < frames - kPathEdges - 1; ++extra) {
      const std::string& parent = path[static_cast<std::size_t>(random() % kPathEdges)];
      buffer.setTransform({{}, parent, "extra_" + std::to_string(extra), wobble(extra)}, "bench",
                          true);
    }
    std::uniform_int_distribution<std::int64_t> time(kStart, newest);
    for (int q = 0; q < 4096; ++q) times.push_back(lcmtf::fromUtime(time(random)));
  }
  lcmtf::BufferCore buffer;
  std::int64_t newest = 0;
  std::vector<lcmtf::TimePoint> times;
};

void lookupAlongFixedPath(benchmark::State& state) {
  const ScalingTree tree(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tree.buffer.lookupTransform("map", "leaf", tree.times[i]));
    i = (i + 1) % tree.times.size();
  }
}

// A tree of `frames` frames built one static edge at a time, each new frame under a random one
// already there; the time per edge added.
void addFramesOneByOne(benchmark::State& state) {
  const auto frames = static_cast<int>(state.range(0));
  std::vector<std::string> names{"map"};
  for (int i = 1; i < frames; ++i) names.push_back("frame_" + std::to_string(i));
  for (auto _ : state) {
    lcmtf::BufferCore buffer;
    std::mt19937 random(9);
    for (int i = 1; i < frames; ++i) {
      const std::string& parent =
          names[static_cast<std::size_t>(random()) % static_cast<std::size_t>(i)];
      buffer.setTransform({{}, parent, names[static_cast<std::size_t>(i)], wobble(i)}, "bench",
                          true);
    }
  }
  state.SetItemsProcessed(state.iterations() * (frames - 1));
}

}  // namespace

BENCHMARK(addFramesOneByOne)->ArgName("frames")->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK(lookupAlongFixedPath)
    ->ArgNames({"frames", "history_s"})
    ->Args({100, 10})
    ->Args({1000, 10})
    ->Args({10000, 10})
    ->Args({100, 1})
    ->Args({100, 60});
BENCHMARK_MAIN();
