// The listening end of the demo: prints, a few times a second, where the gripper is in the
// base frame and where an object the camera saw two seconds ago is now.
// usage: lcmtf_demo_listener [--lcm-url URL] [--duration S] [--rate HZ] [--help]
#include <cmath>
#include <csignal>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>

#include "demo_report.hpp"
#include "lcmtf/transform_listener.hpp"

namespace {

volatile std::sig_atomic_t stop_requested = 0;

// CLI::Range lets NaN through; every number here must be finite.
const CLI::Validator kFinite(
    [](std::string& text) -> std::string {
      double value = 0.0;
      const bool finite = CLI::detail::lexical_cast(text, value) && std::isfinite(value);
      return finite ? std::string() : "'" + text + "' is not a finite number";
    },
    "FINITE");

extern "C" void requestStop(int /*signal*/) { stop_requested = 1; }

}  // namespace

int main(int argc, char** argv) {
  std::string lcm_url;
  double duration = 0.0;
  double rate = 4.0;
  double look_back = 2.0;
  std::vector<double> object{0.0, 0.0, 1.5};
  lcmtf::demo::DemoFrames frames;

  CLI::App app(
      "Prints where the gripper is and where an object seen by the camera a while ago "
      "is now, from the transforms on LCM.",
      "lcmtf_demo_listener");
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: LCM's, which stays on this host)");
  app.add_option("--duration", duration, "Seconds to run; 0 runs until Ctrl-C")
      ->check(kFinite & CLI::Range(0.0, 1e9));
  app.add_option("--rate", rate, "Reports per second")->check(kFinite & CLI::Range(0.1, 100.0));
  app.add_option("--look-back", look_back, "Seconds since the camera saw the object")
      ->check(kFinite & CLI::Range(0.0, 9.0));
  app.add_option("--object", object, "Where the camera saw the object, in its frame")
      ->expected(3)
      ->check(kFinite);
  app.add_option("--base", frames.base)->capture_default_str();
  app.add_option("--end-effector", frames.end_effector)->capture_default_str();
  app.add_option("--camera", frames.camera)->capture_default_str();
  app.add_option("--fixed-frame", frames.fixed)->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
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
    while (!stop_requested && std::chrono::steady_clock::now() < due) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
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
