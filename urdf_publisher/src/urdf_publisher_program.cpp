#include "lcmtf_urdf/urdf_publisher_program.hpp"

#include <iostream>
#include <thread>

#include "command_line_helpers.hpp"
#include "lcmtf/printable.hpp"
#include "lcmtf/programs/lcm_connection.hpp"
#include "lcmtf/programs/stop_signal.hpp"
#include "lcmtf/sendable_names.hpp"
#include "lcmtf_urdf/robot_description.hpp"
#include "lcmtf_urdf/robot_summary.hpp"
#include "program_helpers.hpp"

namespace lcmtf::urdf {

namespace {

constexpr const char* kProgram = "lcmtf-urdf-publisher";

constexpr const char* kDescription =
    "Publishes a robot's frames on LCM: the fixed joints of its URDF as static transforms, "
    "and each joint state as one batch of transforms.";

constexpr const char* kExamples =
    "Examples:\n"
    "  lcmtf-urdf-publisher robot.urdf                 until Ctrl-C\n"
    "  lcmtf-urdf-publisher --check robot.urdf         check it, list every joint, publish "
    "nothing\n"
    "  lcmtf-urdf-publisher --frame-prefix robot1/ robot.urdf\n"
    "  lcmtf-urdf-publisher                            the robot from ROBOT_DESCRIPTION";

// Whether every link can be sent as a frame name after `prefix`; if not, says why.
bool sendable(const RobotModel& robot, const std::string& prefix, const ProgramOutput& output) {
  try {
    requireSendableNames(robot, prefix);
    return true;
  } catch (const UrdfError& e) {
    output.complain(e.what());
    return false;
  }
}

}  // namespace

ParsedCommandLine<UrdfPublisherConfig> parseUrdfPublisherCommandLine(
    const std::vector<std::string>& arguments) {
  ParsedCommandLine<UrdfPublisherConfig> parsed;
  UrdfPublisherConfig config;
  UrdfPublisherOptions& p = config.publisher;
  double resend_seconds = 1.0;

  const auto app_owner = programs::makeToolApp(kProgram, kDescription, kExamples);
  CLI::App& app = *app_owner;
  addRobotSourceOptions(app, {config.urdf_path, config.lcm_url, p.description_channel,
                              p.description_request_channel, p.joint_states.authority});
  app.add_option("--frame-prefix", p.joint_states.frame_prefix,
                 "Written before every link name, as is (e.g. robot1/)")
      ->check(CLI::Validator(
          [](std::string& prefix) { return prefix.empty() ? "" : whyUnsendable(prefix); }, ""));
  app.add_option("--publish-frequency", p.joint_states.publish_frequency,
                 "At most this many batches per second for each joint, on the joint states' "
                 "stamps; 0 publishes every joint state")
      ->check(programs::finiteNumberIn(0.0, 1e6))
      ->type_name("HZ")
      ->capture_default_str();
  app.add_flag("--ignore-timestamp", p.joint_states.ignore_timestamp,
               "Stamp transforms with the time a joint state arrives instead of its utime");
  programs::addChannelOption(app, "--joint-states-channel", p.joint_states_channel,
                             "Channel of joint states");
  programs::addChannelOption(app, "--tf-channel", p.tf_channel, "Channel of dynamic transforms");
  programs::addChannelOption(app, "--static-channel", p.tf_static_channel,
                             "Channel of static transforms");
  programs::addChannelOption(app, "--request-channel", p.tf_static_request_channel,
                             "Channel on which static transforms are asked for again");
  programs::addOldName(app, "--tf-static-channel", p.tf_static_channel);
  programs::addOldName(app, "--tf-static-request-channel", p.tf_static_request_channel);
  app.add_option("--static-resend-period", resend_seconds,
                 "Seconds between resends of the static transforms; 0 sends them only at start "
                 "and when a listener asks")
      ->check(programs::finiteNumberIn(0.0, 3600.0))
      ->type_name("SECONDS")
      ->capture_default_str();
  app.add_flag("--check", config.check_only,
               "Read and check the URDF, say what would be published, and exit");

  if (!parseWith(app, arguments, parsed)) return parsed;
  if (config.check_only && config.urdf_path.empty()) {
    refuse(app, "--check needs a URDF file", parsed);
    return parsed;
  }
  p.static_resend_period = secondsToDuration(resend_seconds);
  parsed.config = std::move(config);
  return parsed;
}

int runUrdfPublisher(const UrdfPublisherConfig& config, const std::atomic<bool>& stop,
                     std::ostream& out, std::ostream& err) {
  const ProgramOutput output{kProgram, out, err};
  UrdfPublisherOptions options = config.publisher;
  options.joint_states.reporter = output.reporter();
  const std::string& prefix = options.joint_states.frame_prefix;

  std::optional<RobotModel> robot = loadFromFile(config.urdf_path, output);
  if (!config.urdf_path.empty() && !robot) return programs::kExitBadArguments;
  if (robot && !sendable(*robot, prefix, output)) return programs::kExitBadArguments;
  if (config.check_only) {
    out << terminalSafe(describeRobot(*robot, prefix, true));
    return 0;
  }
  const std::unique_ptr<lcm::LCM> lcm = programs::openLcmOrReport(config.lcm_url, kProgram, err);
  if (!lcm) return programs::kExitBadArguments;
  if (!robot) {
    robot =
        waitForDescription(*lcm, options.description_channel, options.description_request_channel,
                           options.joint_states.authority, stop, output);
    if (!robot) return 0;
    options.publish_description = false;  // it is another program's to publish
    options.follow_description = true;
  }
  if (!sendable(*robot, prefix, output)) return programs::kExitFailure;
  // Subscribed before it says so, so that whoever waits for the line may publish at once.
  UrdfPublisher publisher(*lcm, std::move(*robot), options);
  output.say(describeRobot(publisher.robot(), prefix) + "  joint states from " +
             options.joint_states_channel + ", transforms to " + options.tf_channel + " and " +
             options.tf_static_channel + ", via '" + programs::describeLcmUrl(config.lcm_url) +
             "'");
  std::uint64_t robots_replaced = 0;
  while (!stop) {
    if (!programs::handleLcmFor(*lcm, std::chrono::milliseconds(100))) {
      output.complain("LCM stopped working at '" + programs::describeLcmUrl(config.lcm_url) + "'");
      return programs::kExitFailure;
    }
    publisher.poll();
    if (publisher.robotsReplaced() != robots_replaced) {
      robots_replaced = publisher.robotsReplaced();
      output.say("a new description replaces the robot: " +
                 describeRobot(publisher.robot(), prefix));
    }
  }
  std::string failures;
  if (publisher.publishFailures() != 0) {
    failures = "; " + std::to_string(publisher.publishFailures()) + " publications failed";
  }
  output.say("stopped after " + describe(publisher.statistics()) + failures);
  return 0;
}

int urdfPublisherMain(int argc, char** argv) {
  const auto parsed =
      parseUrdfPublisherCommandLine(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed.config) {
    (parsed.exit_code == 0 ? std::cout : std::cerr) << parsed.message;
    return parsed.exit_code;
  }
  return runUrdfPublisher(*parsed.config, programs::installStopSignalHandlers(), std::cout,
                          std::cerr);
}

}  // namespace lcmtf::urdf
