#include "lcmtf_viewer/viewer_program.hpp"

#include <cstdlib>
#include <iostream>
#include <mutex>

#include "lcmtf/buffer.hpp"
#include "lcmtf/printable.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/programs/lcm_connection.hpp"
#include "lcmtf/programs/program_authority.hpp"
#include "lcmtf/programs/stop_signal.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf_urdf/robot_model.hpp"
#include "lcmtf_viewer/robot_source.hpp"
#include "lcmtf_viewer/viewer_hub.hpp"
#include "lcmtf_viewer/web_assets.hpp"
#include "lcmtf_viewer/web_server.hpp"
#include "machine_name.hpp"

namespace lcmtf::viewer {

namespace {

constexpr const char* kProgram = "lcmtf-viewer";

constexpr const char* kDescription =
    "Draws the robot and its frames live in a web browser: open the URL it prints. The page "
    "shows every frame and the robot's links in a fixed frame of your choice, lists the tree "
    "with rates and ages, scrubs back through the buffer's history, and can drive the joints "
    "with sliders (off until switched on). It serves only on this machine unless --bind says "
    "otherwise.";

constexpr const char* kExamples =
    "Examples:\n"
    "  lcmtf-viewer                                 the robot from ROBOT_DESCRIPTION, at "
    "http://127.0.0.1:8080/\n"
    "  lcmtf-viewer --urdf robot.urdf --package-path ~/meshes\n"
    "  lcmtf-viewer --bind 0.0.0.0 --port 9000     share it with every machine that can reach "
    "this one";

std::string pageUrl(const std::string& bind_address, std::uint16_t port) {
  std::string host = bind_address;
  if (host == "0.0.0.0" || host == "::") {
    host = machineName();
    if (host.empty()) host = "localhost";
  } else if (host.find(':') != std::string::npos) {
    host = "[" + host + "]";
  }
  return "http://" + host + ":" + std::to_string(port) + "/";
}

MeshSearch meshSearch(const ViewerOptions& options) {
  MeshSearch search;
  for (const std::string& folder : options.package_paths) search.package_paths.emplace_back(folder);
  if (const char* ros = std::getenv("ROS_PACKAGE_PATH")) {
    for (auto& folder : splitPackagePath(ros)) search.package_paths.push_back(std::move(folder));
  }
  return search;
}

}  // namespace

std::optional<int> parseViewerCommandLine(const std::vector<std::string>& args,
                                          ViewerOptions& options, std::ostream& out,
                                          std::ostream& err) {
  const auto app_owner = programs::makeToolApp(kProgram, kDescription, kExamples);
  CLI::App& app = *app_owner;
  app.add_option("--port", options.port, "TCP port of the page; 0 picks a free one")
      ->check(CLI::Range(0, 65535))
      ->type_name("PORT")
      ->capture_default_str();
  app.add_option("--bind", options.bind_address,
                 "Address to serve on. The default serves this machine only; 0.0.0.0 shares "
                 "the page, the robot's meshes and the joint sliders with every machine that "
                 "can reach this one")
      ->type_name("ADDRESS")
      ->capture_default_str();
  app.add_option("--allow-host", options.allowed_hosts,
                 "A name the page may be reached under, besides IP addresses, localhost and this "
                 "machine's name (repeatable; * for any). Requests naming another host are "
                 "refused, so that no web page can reach the viewer under a name of its own")
      ->type_name("NAME")
      ->allow_extra_args(false);
  app.add_option("--allow-origin", options.allowed_origins,
                 "A web page, as http://host:port, that may open the viewer's WebSocket besides "
                 "the viewer's own (repeatable; * for any): it sees the robot and can move its "
                 "joints")
      ->type_name("ORIGIN")
      ->allow_extra_args(false);
  app.add_option("--lcm-url", options.lcm_url,
                 "LCM URL to listen and publish on (default: $LCM_DEFAULT_URL, else " +
                     std::string(programs::lcmBuiltInDefaultUrl()) + ")")
      ->type_name("URL");
  app.add_option("--urdf", options.urdf_path,
                 "The robot's URDF file; without it, the robot comes from "
                 "--description-channel, asked for at start")
      ->check(CLI::Validator(CLI::ExistingFile).description(""))
      ->type_name("FILE");
  app.add_option("--package-path", options.package_paths,
                 "A folder holding packages, for package:// meshes (repeatable; "
                 "ROS_PACKAGE_PATH's folders are searched after these)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  app.add_option("--fixed-frame", options.fixed_frame,
                 "The frame the page draws in at first (default: the robot's root link, else "
                 "the root of the largest tree)")
      ->check(programs::nonEmptyName())
      ->type_name("FRAME");
  app.add_option("--update-rate", options.update_hz, "Scene updates sent to each page per second")
      ->check(programs::positiveFiniteNumberUpTo(60.0))
      ->type_name("HZ")
      ->capture_default_str();
  app.add_option("--stale-after", options.stale_after_s,
                 "A dynamic frame with no new transform for this long is drawn grey")
      ->check(programs::positiveFiniteNumberUpTo(3600.0))
      ->type_name("SECONDS")
      ->capture_default_str();
  app.add_option("--cache-time", options.cache_time_s,
                 "Seconds of history kept per edge: how far back the time slider reaches")
      ->check(programs::positiveFiniteNumberUpTo(3600.0))
      ->type_name("SECONDS")
      ->capture_default_str();
  programs::addStampAheadOption(app, options.max_stamp_ahead_s);
  programs::addChannelOption(app, "--tf-channel", options.tf_channel,
                             "Channel of dynamic transforms");
  programs::addChannelOption(app, "--static-channel", options.static_channel,
                             "Channel of static transforms");
  programs::addChannelOption(app, "--request-channel", options.request_channel,
                             "Channel on which static transforms are asked for again");
  programs::addChannelOption(app, "--description-channel", options.description_channel,
                             "Channel of the robot's URDF text");
  programs::addChannelOption(app, "--description-request-channel",
                             options.description_request_channel,
                             "Channel on which the URDF text is asked for");
  programs::addChannelOption(app, "--joint-states-channel", options.joint_states_channel,
                             "Channel the joint sliders publish on");
  app.add_option("--web-root", options.web_root,
                 "Folder of the page's own files (default: installed beside the program)")
      ->check(CLI::Validator(CLI::ExistingDirectory).description(""))
      ->type_name("DIR");
  options.three_dir = kDefaultThreeJsDir;
  app.add_option("--three-dir", options.three_dir, "Folder of three.js (Debian's libjs-three)")
      ->check(CLI::Validator(CLI::ExistingDirectory).description(""))
      ->type_name("DIR")
      ->capture_default_str();
  app.add_option("--duration", options.duration_s, "Stop after this many seconds (0: never)")
      ->check(programs::finiteNumberIn(0.0, 1e9))
      ->type_name("SECONDS");
  return programs::parseCommandLine(app, args, out, err);
}

int runViewer(const ViewerOptions& options, std::ostream& out, std::ostream& err,
              const std::atomic<bool>& stop) {
  const std::string authority = programs::programAuthority(kProgram);
  std::mutex err_mutex;
  auto report = [&](const std::string& message) {
    std::lock_guard<std::mutex> lock(err_mutex);
    err << kProgram << ": " << terminalSafe(message) << std::endl;
  };

  const std::unique_ptr<lcm::LCM> lcm = programs::openLcmOrReport(options.lcm_url, kProgram, err);
  if (!lcm) return programs::kExitBadArguments;
  ServedFiles page_files;
  try {
    page_files = pageFiles(
        options.web_root.empty() ? defaultWebRoot() : std::filesystem::path(options.web_root),
        options.three_dir);
  } catch (const std::exception& e) {
    report(e.what());
    return programs::kExitFailure;
  }

  Buffer buffer(secondsToDuration(options.cache_time_s));
  buffer.setErrorReporter(nullptr);
  ListenerOptions listening;
  listening.lcm_url = options.lcm_url;
  listening.channel = options.tf_channel;
  listening.static_channel = options.static_channel;
  listening.static_request_channel = options.request_channel;
  listening.authority = authority;
  listening.reporter = report;
  listening.max_stamp_ahead = secondsToDuration(options.max_stamp_ahead_s);
  TransformListener listener(buffer, listening);

  HubSettings settings;
  settings.version = programs::toolsVersion();
  settings.fixed_frame = options.fixed_frame;
  settings.update_hz = options.update_hz;
  settings.stale_after = secondsToDuration(options.stale_after_s);
  settings.joint_states_channel = options.joint_states_channel;
  settings.authority = authority;
  ViewerHub hub(buffer, std::move(page_files), settings,
                [&lcm, &options](const joint_state_t& state) {
                  lcm->publish(options.joint_states_channel, &state);
                });

  WebServerOptions serving;
  serving.bind_address = options.bind_address;
  serving.port = static_cast<std::uint16_t>(options.port);
  serving.allowed_hosts = options.allowed_hosts;
  serving.allowed_origins = options.allowed_origins;
  std::unique_ptr<WebServer> server;
  try {
    server = std::make_unique<WebServer>(serving, hub);
  } catch (const std::exception& e) {
    report(e.what());
    return programs::kExitFailure;
  }
  using std::chrono::microseconds;
  server->every(secondsToDuration(1.0 / options.update_hz), [&hub] { hub.sendScenes(); });
  server->every(std::chrono::milliseconds(500), [&hub] { hub.sendTree(); });
  server->every(microseconds(1'000'000 / 30), [&hub] { hub.publishJoints(); });

  RobotSourceOptions robot_options;
  robot_options.description_channel = options.description_channel;
  robot_options.request_channel = options.description_request_channel;
  robot_options.authority = authority;
  robot_options.search = meshSearch(options);
  WebServer& web = *server;
  RobotSource robot_source(
      *lcm, robot_options,
      [&](std::shared_ptr<const RobotView> robot) {
        const std::string name = robot->robot.value("name", std::string());
        const std::size_t warnings = robot->warnings.size();
        report("robot '" + name + "' from " + robot->robot.value("source", std::string()) + ": " +
               std::to_string(robot->robot.at("links").size()) + " links, " +
               std::to_string(robot->meshes.size()) + " mesh files, " + std::to_string(warnings) +
               (warnings == 1 ? " warning" : " warnings"));
        for (const std::string& warning : robot->warnings) report("  " + warning);
        web.post([&hub, robot = std::move(robot)] { hub.setRobot(robot); });
      },
      report);
  if (!options.urdf_path.empty()) {
    try {
      robot_source.loadFile(options.urdf_path);
    } catch (const urdf::UrdfError& e) {
      report(e.what());
      return programs::kExitBadArguments;
    }
  } else {
    robot_source.follow();
  }

  server->start();
  out << kProgram << ": open " << pageUrl(options.bind_address, server->port())
      << " in a browser\n  transforms from " << options.tf_channel << " and "
      << options.static_channel << ", robot from "
      << (options.urdf_path.empty() ? options.description_channel : options.urdf_path)
      << ", joint sliders to " << options.joint_states_channel << ", via '"
      << programs::describeLcmUrl(options.lcm_url) << "'" << std::endl;

  const TimePoint started = now();
  while (!stop.load()) {
    if (options.duration_s > 0 && now() - started >= secondsToDuration(options.duration_s)) break;
    robot_source.askIfWaiting(now());
    if (!programs::handleLcmFor(*lcm, std::chrono::milliseconds(100))) {
      report("LCM stopped receiving");
      break;
    }
  }
  server->stop();
  const WebServerStatistics& web_counts = server->statistics();
  const HubStatistics& hub_counts = hub.statistics();
  out << kProgram << ": served " << web_counts.files_sent << " files to " << hub_counts.pages_opened
      << " pages; refused " << web_counts.requests_refused << " requests and "
      << hub_counts.messages_refused + web_counts.messages_too_large << " page messages"
      << std::endl;
  return programs::kExitSuccess;
}

int viewerMain(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  ViewerOptions options;
  if (const auto status = parseViewerCommandLine(args, options, std::cout, std::cerr)) {
    return *status;
  }
  return runViewer(options, std::cout, std::cerr, programs::installStopSignalHandlers());
}

}  // namespace lcmtf::viewer
