// A listener on its own thread, flooded over udpm (ttl=0) with batches far larger than robots
// send, as fast as a sender thread can publish them: the process's memory second by second,
// which is what LCM holds waiting for the listener. The kernel drops most pieces of such
// batches unless its receive buffer is raised (net.core.rmem_max and rmem_default, as LCM's
// guide advises for large messages); the bench says what it found.
// Usage: listener_queue_bench [--seconds 20] [--transforms 60000] [--name-bytes 200]
//                             [--queue-bytes N (default: ListenerOptions')] [--port 7739]
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include "lcmtf/transform_listener.hpp"
#include "positive_flags.hpp"
#include "process_memory.hpp"

namespace {

struct QueueBenchOptions {
  int seconds = 20;
  int transforms = 60000;
  std::size_t name_bytes = 200;
  std::size_t queue_bytes = lcmtf::ListenerOptions{}.queue_bytes;
  int port = 7739;
};

long kernelSetting(const char* path) {
  std::ifstream file(path);
  long value = -1;
  file >> value;
  return value;
}

// A batch of `count` transforms, each naming a frame of its own under one parent.
lcmtf::tf_message_t largeBatch(int count, std::size_t name_bytes) {
  lcmtf::tf_message_t batch;
  batch.authority = "flood";
  batch.sequence = 0;
  batch.num_transforms = count;
  batch.transforms.resize(static_cast<std::size_t>(count));
  const std::string padding(name_bytes, 'p');
  for (int i = 0; i < count; ++i) {
    lcmtf::transform_t& t = batch.transforms[static_cast<std::size_t>(i)];
    t.parent_frame = "base_" + padding;
    t.child_frame = "frame_" + std::to_string(i) + "_" + padding;
    t.translation = {0.1, 0.1, 0.1};
    t.rotation = {0.0, 0.0, 0.0, 1.0};
  }
  return batch;
}

}  // namespace

int main(int argc, char** argv) {
  QueueBenchOptions options;
  if (!bench::parsePositiveFlags(argc, argv,
                                 {{"--seconds", bench::into(options.seconds)},
                                  {"--transforms", bench::into(options.transforms)},
                                  {"--name-bytes", bench::into(options.name_bytes)},
                                  {"--queue-bytes", bench::into(options.queue_bytes)},
                                  {"--port", bench::into(options.port)}})) {
    std::fprintf(stderr,
                 "usage: listener_queue_bench [--seconds N] [--transforms N] [--name-bytes N] "
                 "[--queue-bytes N] [--port N]  (positive numbers)\n");
    return 2;
  }
  const std::string url = "udpm://239.255.76.67:" + std::to_string(options.port) + "?ttl=0";
  lcmtf::Buffer buffer;
  lcmtf::ListenerOptions listener_options;
  listener_options.lcm_url = url;
  listener_options.queue_bytes = options.queue_bytes;
  listener_options.request_statics_at_start = false;
  listener_options.reporter = nullptr;
  lcmtf::TransformListener listener(buffer, listener_options);
  lcm::LCM sender_lcm(url);
  lcmtf::tf_message_t batch = largeBatch(options.transforms, options.name_bytes);
  const int batch_bytes = batch.getEncodedSize();

  const long receive_buffer = kernelSetting("/proc/sys/net/core/rmem_default");
  std::printf("%s: batches of %d transforms (%d bytes) for %d s; listener queue_bytes %zu\n",
              url.c_str(), options.transforms, batch_bytes, options.seconds, options.queue_bytes);
  std::printf(
      "kernel receive buffer: rmem_default %ld, rmem_max %ld bytes%s\n", receive_buffer,
      kernelSetting("/proc/sys/net/core/rmem_max"),
      receive_buffer < batch_bytes ? " (below a batch: pieces of batches will be lost)" : "");
  const double rss_before = bench::processMemoryMegabytes("VmRSS:");

  std::atomic<bool> stop{false};
  std::uint64_t sent = 0;
  std::thread flood([&] {
    while (!stop) {
      batch.utime = lcmtf::toUtime(lcmtf::now());
      batch.sequence = static_cast<std::int64_t>(++sent);
      for (lcmtf::transform_t& t : batch.transforms) t.utime = batch.utime;
      sender_lcm.publish(lcmtf::kTfChannel, &batch);
    }
  });
  for (int second = 1; second <= options.seconds; ++second) {
    std::this_thread::sleep_for(std::chrono::seconds(1));
    const lcmtf::ListenerStatistics stats = listener.statistics();
    std::printf("%3d s: RSS %8.1f MB, batches stored %6llu, queue shortened %llu\n", second,
                bench::processMemoryMegabytes("VmRSS:"),
                static_cast<unsigned long long>(stats.messages),
                static_cast<unsigned long long>(stats.queue_shortened));
    std::fflush(stdout);
  }
  stop = true;
  flood.join();
  std::printf("RSS before %.1f MB, peak %.1f MB; %llu batches sent, %llu stored\n", rss_before,
              bench::processMemoryMegabytes("VmHWM:"), static_cast<unsigned long long>(sent),
              static_cast<unsigned long long>(listener.statistics().messages));
  return 0;
}
