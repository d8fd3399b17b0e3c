// The other process of the transport tests: broadcasts known transforms over LCM until it is
// killed or its time is up.
//   transport_peer static URL [--no-resend] [MAX_MS]
//     a StaticTransformBroadcaster (own LCM thread) holding peerStatics(); with --no-resend it
//     publishes them once at start and then only when a listener asks.
//   transport_peer dynamic URL RATE_HZ DURATION_MS ORIGIN_UTIME SPEED
//     a TransformBroadcaster sending odom -> base = odomTBase(stamp, ORIGIN_UTIME, SPEED),
//     stamped with now(), RATE_HZ times a second for DURATION_MS.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <thread>

#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "support/transport_motion.hpp"

namespace {

using Clock = std::chrono::steady_clock;

int usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s static URL [--no-resend] [MAX_MS]\n"
               "       %s dynamic URL RATE_HZ DURATION_MS ORIGIN_UTIME SPEED\n",
               program, program);
  return 2;
}

int runStatic(const std::string& url, bool resend, std::chrono::milliseconds max_duration) {
  lcmtf::StaticBroadcasterOptions options;
  options.lcm_url = url;
  if (!resend) options.resend_period = lcmtf::Duration::zero();
  lcmtf::StaticTransformBroadcaster broadcaster(options);
  if (!broadcaster.sendTransform(lcmtf_test::peerStatics())) {
    std::fprintf(stderr, "transport_peer: cannot publish on %s\n", url.c_str());
    return 3;
  }
  std::this_thread::sleep_for(max_duration);
  return 0;
}

int runDynamic(const std::string& url, double rate_hz, std::chrono::milliseconds duration,
               lcmtf::TimePoint origin, double speed) {
  lcmtf::TransformBroadcaster broadcaster(url);
  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz));
  const Clock::time_point end = Clock::now() + duration;
  for (Clock::time_point tick = Clock::now(); tick < end; tick += period) {
    std::this_thread::sleep_until(tick);
    const lcmtf::TimePoint stamp = lcmtf::now();
    if (!broadcaster.sendTransform(lcmtf::TransformStamped{
            stamp, "odom", "base", lcmtf_test::odomTBase(stamp, origin, speed)})) {
      std::fprintf(stderr, "transport_peer: cannot publish on %s\n", url.c_str());
      return 3;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage(argv[0]);
  const std::string mode = argv[1];
  const std::string url = argv[2];
  try {
    if (mode == "static" && argc <= 5) {
      bool resend = true;
      std::chrono::milliseconds max_duration(30000);
      for (int i = 3; i < argc; ++i) {
        if (std::string(argv[i]) == "--no-resend") {
          resend = false;
        } else {
          max_duration = std::chrono::milliseconds(std::atoll(argv[i]));
        }
      }
      return runStatic(url, resend, max_duration);
    }
    if (mode == "dynamic" && argc == 7) {
      return runDynamic(url, std::atof(argv[3]), std::chrono::milliseconds(std::atoll(argv[4])),
                        lcmtf::fromUtime(std::atoll(argv[5])), std::atof(argv[6]));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "transport_peer: %s\n", e.what());
    return 3;
  }
  return usage(argv[0]);
}
