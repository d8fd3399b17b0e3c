// A listener flooded with batches from a new authority name each, beside a 1 kHz sender of
// good batches, all over one in-process LCM (memq): memory before and after, and how many
// good batches reached the buffer.
// Usage: listener_flood_bench [--seconds 60] [--flood-rate 15000] [--name-bytes 250]
#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/transform_listener.hpp"
#include "positive_flags.hpp"
#include "process_memory.hpp"

namespace {

struct FloodOptions {
  int seconds = 60;
  int flood_rate = 15000;  // new authorities a second
  std::size_t name_bytes = 250;
};

std::string floodName(std::uint64_t n, std::size_t bytes) {
  std::string name = "flood_" + std::to_string(n) + "_";
  name.resize(std::max(bytes, name.size()), 'x');
  return name;
}

lcmtf::TransformStamped sample(const char* parent, const char* child, double x) {
  return lcmtf::TransformStamped{
      lcmtf::now(), parent, child,
      lcmtf::Transform(Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity())};
}

}  // namespace

int main(int argc, char** argv) {
  FloodOptions options;
  if (!bench::parsePositiveFlags(argc, argv,
                                 {{"--seconds", bench::into(options.seconds)},
                                  {"--flood-rate", bench::into(options.flood_rate)},
                                  {"--name-bytes", bench::into(options.name_bytes)}})) {
    std::fprintf(stderr,
                 "usage: listener_flood_bench [--seconds N] [--flood-rate PER_SECOND] "
                 "[--name-bytes N]  (positive numbers)\n");
    return 2;
  }
  lcm::LCM lcm("memq://");
  lcmtf::Buffer buffer;
  lcmtf::ListenerOptions listener_options;
  listener_options.reporter = nullptr;
  lcmtf::TransformListener listener(buffer, lcm, listener_options);
  std::atomic<bool> stop{false};
  std::thread receiver([&] {
    while (!stop) lcm.handleTimeout(10);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const double rss_before = bench::processMemoryMegabytes("VmRSS:");

  std::uint64_t good_sent = 0;
  std::uint64_t flood_sent = 0;
  std::thread good([&] {
    lcmtf::TransformBroadcaster odometry(lcm, lcmtf::kTfChannel, "odometry");
    auto next = std::chrono::steady_clock::now();
    while (!stop) {
      odometry.sendTransform(sample("odom", "base", 1.0));
      ++good_sent;
      next += std::chrono::milliseconds(1);
      std::this_thread::sleep_until(next);
    }
  });
  const auto start = std::chrono::steady_clock::now();
  const auto end = start + std::chrono::seconds(options.seconds);
  auto tick = start;
  const int per_tick = std::max(1, options.flood_rate / 1000);
  while (std::chrono::steady_clock::now() < end) {
    for (int i = 0; i < per_tick; ++i) {
      lcmtf::tf_message_t batch = lcmtf::makeTfMessage({sample("map", "flooded", 0.0)},
                                                       floodName(flood_sent++, options.name_bytes));
      batch.sequence = 1;
      lcm.publish(lcmtf::kTfChannel, &batch);
    }
    tick += std::chrono::milliseconds(1);
    std::this_thread::sleep_until(tick);
  }
  stop = true;
  good.join();
  receiver.join();
  while (lcm.handleTimeout(0) > 0) {
  }

  const lcmtf::ListenerStatistics stats = listener.statistics();
  std::uint64_t good_received = 0;
  std::uint64_t good_lost = 0;
  for (const lcmtf::AuthorityStatistics& authority : listener.authorityStatistics()) {
    if (authority.authority != "odometry") continue;
    good_received = authority.batches;
    good_lost = authority.lost_batches;
  }
  std::printf("%d s: %llu authority names of %zu bytes (%d a second) beside 1 kHz good batches\n",
              options.seconds, static_cast<unsigned long long>(flood_sent), options.name_bytes,
              options.flood_rate);
  std::printf("RSS before %.1f MB, after %.1f MB, peak %.1f MB\n", rss_before,
              bench::processMemoryMegabytes("VmRSS:"), bench::processMemoryMegabytes("VmHWM:"));
  std::printf(
      "good batches stored %llu of %llu sent (%.2f %%); lost as counted by number %llu\n",
      static_cast<unsigned long long>(good_received), static_cast<unsigned long long>(good_sent),
      good_sent ? 100.0 * static_cast<double>(good_received) / static_cast<double>(good_sent) : 0.0,
      static_cast<unsigned long long>(good_lost));
  std::printf("listener: %llu batches accepted, %llu authorities followed, %llu forgotten\n",
              static_cast<unsigned long long>(stats.messages),
              static_cast<unsigned long long>(stats.authorities_followed),
              static_cast<unsigned long long>(stats.authorities_forgotten));
  return 0;
}
