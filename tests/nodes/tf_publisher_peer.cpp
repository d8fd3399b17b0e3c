// Publishes one dynamic edge at a fixed rate, as a robot's broadcaster would, for the tools'
// process tests: every tick a batch on TF with the stamp of that tick.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "lcmtf/transform_broadcaster.hpp"

int main(int argc, char** argv) {
  if (argc != 14) {
    std::fprintf(stderr,
                 "usage: %s URL AUTHORITY RATE_HZ DURATION_MS PARENT CHILD X Y Z QX QY QZ QW\n",
                 argv[0]);
    return 2;
  }
  const double rate_hz = std::atof(argv[3]);
  const auto duration = std::chrono::milliseconds(std::atoll(argv[4]));
  lcmtf::TransformStamped parent_T_child;
  parent_T_child.parent_frame = argv[5];
  parent_T_child.child_frame = argv[6];
  parent_T_child.transform.translation = {std::atof(argv[7]), std::atof(argv[8]),
                                          std::atof(argv[9])};
  parent_T_child.transform.rotation = Eigen::Quaterniond(std::atof(argv[13]), std::atof(argv[10]),
                                                         std::atof(argv[11]), std::atof(argv[12]))
                                          .normalized();
  try {
    lcmtf::TransformBroadcaster broadcaster(argv[1], lcmtf::kTfChannel, argv[2]);
    using Clock = std::chrono::steady_clock;
    const auto period =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz));
    const Clock::time_point end = Clock::now() + duration;
    for (Clock::time_point tick = Clock::now(); tick < end; tick += period) {
      std::this_thread::sleep_until(tick);
      parent_T_child.stamp = lcmtf::now();
      if (!broadcaster.sendTransform(parent_T_child)) {
        std::fprintf(stderr, "tf_publisher_peer: cannot publish on %s\n", argv[1]);
        return 3;
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tf_publisher_peer: %s\n", e.what());
    return 3;
  }
  return 0;
}
