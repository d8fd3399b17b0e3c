// The listening end of the demo: prints, a few times a second, where the gripper is in the
// base frame and where an object the camera saw two seconds ago is now.
// usage: lcmtf_demo_listener [--lcm-url URL] [--duration S] [--rate HZ] [--help]
#include <iostream>

#include "demo_report.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/programs/stop_signal.hpp"
#include "lcmtf/transform_listener.hpp"

using lcmtf::programs::finiteNumber;
using lcmtf::programs::finiteNumberIn;

int main(int argc, char** argv) {
  std::string lcm_url;
  double duration = 0.0;
  double rate = 4.0;
  double look_back = 2.0;
  std::vector<double> object{0.0, 0.0, 1.5};
  lcmtf::demo::DemoFrames frames;

  const auto app = lcmtf::programs::makeToolApp(
      "lcmtf_demo_listener",
      "Prints where the gripper is and where an object seen by the camera a while ago is now, "
      "from the transforms on LCM.",
      "Example:\n  lcmtf_demo_listener --duration 10 --look-back 1");
  app->add_option("--lcm-url", lcm_url, "LCM URL (default: LCM's, which stays on this host)");
  app->add_option("--duration", duration, "Seconds to run; 0 runs until Ctrl-C")
      ->check(finiteNumberIn(0.0, 1e9));
  app->add_option("--rate", rate, "Reports per second")->check(finiteNumberIn(0.1, 100.0));
  app->add_option("--look-back", look_back, "Seconds since the camera saw the object")
      ->check(finiteNumberIn(0.0, 9.0));
  app->add_option("--object", object, "Where the camera saw the object, in its frame")
      ->expected(3)
      ->check(finiteNumber());
  app->add_option("--base", frames.base)->capture_default_str();
  app->add_option("--end-effector", frames.end_effector)->capture_default_str();
  app->add_option("--camera", frames.camera)->capture_default_str();
  app->add_option("--fixed-frame", frames.fixed)->capture_default_str();
  if (const auto status = lcmtf::programs::parseCommandLine(
          *app, std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr)) {
    return *status;
  }

  const std::atomic<bool>& stop_requested = lcmtf::programs::installStopSignalHandlers();
  lcmtf::Buffer buffer;
  lcmtf::ListenerOptions options;
  options.lcm_url = lcm_url;
  lcmtf::TransformListener listener(buffer, options);

  const Eigen::Vector3d object_in_camera(object[0], object[1], object[2]);
  const auto start = std::chrono::steady_clock::now();
  const auto period = std::chrono::duration<double>(1.0 / rate);
  auto last_waiting_note = start - std::chrono::hours(1);
  int reports = 0;
  for (int tick = 1; !stop_requested; ++tick) {
    const auto due =
        start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(period * tick);
    if (lcmtf::programs::sleepUnlessStopped(std::chrono::duration_cast<std::chrono::milliseconds>(
                                                due - std::chrono::steady_clock::now()),
                                            stop_requested)) {
      break;
    }
    const auto now = std::chrono::steady_clock::now();
    if (duration > 0.0 && now - start >= std::chrono::duration<double>(duration)) break;
    std::string why;
    const auto report = lcmtf::demo::makeDemoReport(
        buffer, frames, lcmtf::secondsToDuration(look_back), object_in_camera, &why);
    if (report) {
      std::cout << lcmtf::demo::formatDemoReport(*report, frames) << std::endl;
      ++reports;
    } else if (now - last_waiting_note >= std::chrono::seconds(1)) {
      std::cout << "waiting for transforms: " << why << std::endl;
      last_waiting_note = now;
    }
  }
  if (reports == 0 && !stop_requested) {
    std::cerr << "lcmtf_demo_listener: no report in " << duration
              << " s: are lcmtf-joint-publisher and lcmtf-urdf-publisher running on this URL?\n";
    return 1;
  }
  return 0;
}
