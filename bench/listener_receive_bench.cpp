// What a transform costs on its way in: the batches a state publisher sends (the next sample of
// every dynamic edge of the tree) handed to a TransformListener as LCM delivers them, beside the
// two parts of that way measured alone (decoding the bytes, storing the decoded batch in a
// BufferCore) and, where ROS tf2 is installed, tf2::BufferCore storing the same samples one by
// one. Each edge's history is full before the timing starts, so every sample stored drops the
// edge's oldest, as on a robot that has run a while. The rounds alternate between the four;
// the table gives each one's fastest round, in ns per transform, and the spread over rounds.
// Usage: listener_receive_bench [--rounds 9] [--batches 1000]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf/wire_decode.hpp"
#include "positive_flags.hpp"
#include "tree_shapes.hpp"
#ifdef LCMTF_BENCH_WITH_TF2
#include "tf2_subject.hpp"
#endif

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  int rounds = 9;
  int batches = 1000;  // per round
};

lcmtf::Transform transformOf(const bench::Pose& p) {
  return lcmtf::Transform(Eigen::Vector3d(p.x, p.y, p.z),
                          Eigen::Quaterniond(p.qw, p.qx, p.qy, p.qz));
}

// A state publisher's batch for each step of the workload's motion: the step's sample of every
// dynamic edge, with the poses the insert rows of buffer_core_bench give.
class Publisher {
 public:
  explicit Publisher(const bench::Workload& w) : w_(w), dynamic_(bench::dynamicEdges(w)) {
    for (std::size_t index : dynamic_) {
      const bench::Edge& edge = w.edges[index];
      batch_.push_back(lcmtf::TransformStamped{lcmtf::TimePoint{}, w.names[edge.parent],
                                               w.names[edge.child], lcmtf::Transform::identity()});
    }
  }

  std::size_t batchSize() const { return batch_.size(); }

  const std::vector<lcmtf::TransformStamped>& batch(std::size_t step) {
    for (std::size_t i = 0; i < dynamic_.size(); ++i) {
      const bench::Edge& edge = w_.edges[dynamic_[i]];
      batch_[i].stamp = lcmtf::fromUtime(w_.stamp(edge, step));
      batch_[i].transform = transformOf(bench::insertedPose(edge, step));
    }
    return batch_;
  }

  const std::vector<std::uint8_t>& encoded(std::size_t step) {
    lcmtf::tf_message_t message = lcmtf::makeTfMessage(batch(step), "robot_state_publisher");
    message.sequence = static_cast<std::int64_t>(step + 1);
    bytes_.resize(static_cast<std::size_t>(message.getEncodedSize()));
    message.encode(bytes_.data(), 0, static_cast<int>(bytes_.size()));
    return bytes_;
  }

 private:
  const bench::Workload& w_;
  std::vector<std::size_t> dynamic_;
  std::vector<lcmtf::TransformStamped> batch_;
  std::vector<std::uint8_t> bytes_;
};

// One way in, timed batch by batch: `prepare(step)` (untimed) readies the step's batch and
// `take()` hands it over.
struct Way {
  Way(const char* way_name, std::function<void(std::size_t)> prepare_step,
      std::function<void()> take_batch)
      : name(way_name), prepare(std::move(prepare_step)), take(std::move(take_batch)) {}

  const char* name;
  std::function<void(std::size_t step)> prepare;
  std::function<void()> take;
  std::size_t next_step = 0;
  std::vector<double> rounds;  // ns per transform

  void fill(std::size_t steps) {
    for (; next_step < steps; ++next_step) {
      prepare(next_step);
      take();
    }
  }

  void round(int batches, std::size_t batch_size) {
    double ns = 0;
    for (int b = 0; b < batches; ++b, ++next_step) {
      prepare(next_step);
      const auto start = Clock::now();
      take();
      ns += std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    }
    rounds.push_back(ns / (static_cast<double>(batches) * static_cast<double>(batch_size)));
  }
};

void printWay(const Way& way) {
  const auto [fastest, slowest] = std::minmax_element(way.rounds.begin(), way.rounds.end());
  std::printf("  %-48s %8.1f %7.1f%%\n", way.name, *fastest,
              100.0 * (*slowest - *fastest) / *fastest);
}

void measure(const bench::Workload& w, const Options& options) {
  Publisher publisher(w);
  const std::size_t batch_size = publisher.batchSize();

  lcm::LCM lcm("memq://");
  lcmtf::Buffer listened(lcmtf::Duration(w.history()));
  lcmtf::ListenerOptions listener_options;
  listener_options.request_statics_at_start = false;
  lcmtf::TransformListener listener(listened, lcm, listener_options);
  const std::vector<std::uint8_t>* bytes = nullptr;
  Way receive{"listener.handleMessage (decode + check + store)",
              [&](std::size_t step) { bytes = &publisher.encoded(step); },
              [&] { listener.handleMessage(bytes->data(), bytes->size(), lcmtf::kTfChannel); }};

  lcmtf::tf_message_t decoded;
  Way decode{"decodeMessage into a reused tf_message_t",
             [&](std::size_t step) { bytes = &publisher.encoded(step); },
             [&] { lcmtf::decodeMessage(bytes->data(), bytes->size(), decoded); }};

  lcmtf::BufferCore stored(lcmtf::Duration(w.history()));
  const std::vector<lcmtf::TransformStamped>* batch = nullptr;
  Way store{"BufferCore::setTransforms of the decoded batch",
            [&](std::size_t step) { batch = &publisher.batch(step); },
            [&] { stored.setTransforms(*batch, "robot_state_publisher"); }};

  std::vector<Way*> ways{&receive, &decode, &store};
#ifdef LCMTF_BENCH_WITH_TF2
  bench::Tf2Subject tf2(w);
  const std::vector<std::size_t> dynamic = bench::dynamicEdges(w);
  std::size_t tf2_step = 0;
  Way tf2_store{"tf2::BufferCore::setTransform, one by one",
                [&](std::size_t step) { tf2_step = step; },
                [&] {
                  for (std::size_t index : dynamic) {
                    const bench::Edge& edge = w.edges[index];
                    tf2.set(index, w.stamp(edge, tf2_step), bench::insertedPose(edge, tf2_step));
                  }
                }};
  ways.push_back(&tf2_store);
#endif
  // Static edges once, then every dynamic edge's history filled.
  for (std::size_t index = 0; index < w.edges.size(); ++index) {
    const bench::Edge& edge = w.edges[index];
    if (edge.dynamic) continue;
#ifdef LCMTF_BENCH_WITH_TF2
    tf2.set(index, 0, edge.samples[0], true);
#endif
    const lcmtf::TransformStamped fixed{lcmtf::TimePoint{}, w.names[edge.parent],
                                        w.names[edge.child], transformOf(edge.samples[0])};
    listened.setTransform(fixed, "static_publisher", true);
    stored.setTransform(fixed, "static_publisher", true);
  }
  for (Way* way : ways) way->fill(w.samples);
  for (int r = 0; r < options.rounds; ++r) {
    for (Way* way : ways) way->round(options.batches, batch_size);
  }
  const lcmtf::ListenerStatistics statistics = listener.statistics();
  std::printf(
      "%s: %zu frames, batches of %zu transforms; %llu stored by the listener, %llu "
      "refused\n",
      w.shape.c_str(), w.frameCount(), batch_size,
      static_cast<unsigned long long>(statistics.transforms),
      static_cast<unsigned long long>(statistics.rejected_transforms + statistics.frame_limit +
                                      statistics.malformed));
  std::printf("  %-48s %8s %8s\n", "ns per transform", "fastest", "spread");
  for (const Way* way : ways) printWay(*way);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!bench::parsePositiveFlags(argc, argv,
                                 {{"--rounds", bench::into(options.rounds)},
                                  {"--batches", bench::into(options.batches)}})) {
    std::fprintf(stderr, "usage: listener_receive_bench [--rounds N] [--batches N]\n");
    return 2;
  }
  measure(bench::makePr2Workload(), options);
  measure(bench::makeDeepChainWorkload(), options);
  measure(bench::makeWideWorkload(), options);
  return 0;
}
