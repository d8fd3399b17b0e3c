#include "lcmtf_urdf/joint_publisher_program.hpp"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "command_line_helpers.hpp"
#include "lcmtf/batch_numbering.hpp"
#include "lcmtf/programs/lcm_connection.hpp"
#include "lcmtf/programs/number_text.hpp"
#include "lcmtf/programs/stop_signal.hpp"
#include "lcmtf_urdf/joint_state_sources.hpp"
#include "program_helpers.hpp"

namespace lcmtf::urdf {

namespace {

constexpr const char* kProgram = "lcmtf-joint-publisher";
// The longest a Ctrl-C waits for between two joint states at a low rate.
constexpr auto kLongestNap = std::chrono::milliseconds(20);

constexpr const char* kDescription =
    "Publishes joint states for every movable joint of a robot that follows no other: at "
    "rest (zero, or the middle of the limits when zero is outside them), or sweeping. Mimic "
    "joints are published too, following their leaders.";

constexpr const char* kExamples =
    "Examples:\n"
    "  lcmtf-joint-publisher robot.urdf --sweep       every joint moving within its limits\n"
    "  lcmtf-joint-publisher robot.urdf --position elbow_joint=0.5\n"
    "  lcmtf-joint-publisher --duration 10 robot.urdf";

// "NAME=VALUE" split at the last '=', the value a finite number; nothing otherwise.
std::optional<std::pair<std::string, double>> heldJoint(const std::string& text) {
  const auto equals = text.rfind('=');
  if (equals == std::string::npos || equals == 0) return std::nullopt;
  const std::optional<double> value = programs::strictNumber(text.substr(equals + 1));
  if (!value) return std::nullopt;
  return std::make_pair(text.substr(0, equals), *value);
}

CLI::Validator heldJointSyntax() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return heldJoint(text) ? std::string()
                               : "'" + text + "' is not JOINT=VALUE with a finite VALUE";
      },
      "JOINT=VALUE");
}

std::vector<std::pair<std::string, double>> splitHeld(const std::vector<std::string>& texts) {
  std::vector<std::pair<std::string, double>> held;
  for (const std::string& text : texts) held.push_back(*heldJoint(text));  // checked
  return held;
}

// Handles what the sources send until `when`; false when LCM fails.
bool handleUntil(lcm::LCM& lcm, std::chrono::steady_clock::time_point when,
                 const std::atomic<bool>& stop) {
  while (!stop) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= when) return true;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(when - now);
    if (!programs::handleLcmFor(lcm, std::clamp(left, std::chrono::milliseconds(1), kLongestNap))) {
      return false;
    }
  }
  return true;
}

}  // namespace

ParsedCommandLine<JointPublisherConfig> parseJointPublisherCommandLine(
    const std::vector<std::string>& arguments) {
  ParsedCommandLine<JointPublisherConfig> parsed;
  JointPublisherConfig config;
  std::vector<std::string> held;

  const auto app_owner = programs::makeToolApp(kProgram, kDescription, kExamples);
  CLI::App& app = *app_owner;
  addRobotSourceOptions(app, {config.urdf_path, config.lcm_url, config.description_channel,
                              config.description_request_channel, config.authority});
  programs::addChannelOption(app, "--joint-states-channel", config.channel,
                             "Channel of the joint states");
  programs::addOldName(app, "--channel", config.channel);
  app.add_option("--rate", config.rate, "Joint states per second")
      ->check(programs::finiteNumberIn(0.01, 10000.0))
      ->capture_default_str();
  app.add_flag("--sweep", config.generator.sweep,
               "Move every joint smoothly within its limits; continuous joints turn");
  app.add_option("--sweep-period", config.generator.sweep_period,
                 "Seconds of the slowest joint's swing or turn")
      ->check(programs::finiteNumberIn(0.1, 3600.0))
      ->capture_default_str();
  app.add_option("--position", held, "Hold a joint at a position (repeatable), e.g. elbow=0.5")
      ->allow_extra_args(false)
      ->check(heldJointSyntax());
  app.add_option("--source", config.sources,
                 "Channel of joint states whose positions are published in place of the "
                 "generated ones, latest first (repeatable)")
      ->allow_extra_args(false)
      ->check(programs::nonEmptyName())
      ->type_name("CHANNEL");
  app.add_option("--duration", config.duration, "Seconds to run; 0 runs until Ctrl-C")
      ->check(programs::finiteNumberIn(0.0, 1e9))
      ->capture_default_str();

  if (!parseWith(app, arguments, parsed)) return parsed;
  for (const std::string& source : config.sources) {
    if (source == config.channel) {
      refuse(app, "--source " + source + " is the channel it publishes on", parsed);
      return parsed;
    }
  }
  config.generator.held = splitHeld(held);
  parsed.config = std::move(config);
  return parsed;
}

int runJointPublisher(const JointPublisherConfig& config, const std::atomic<bool>& stop,
                      std::ostream& out, std::ostream& err) {
  const ProgramOutput output{kProgram, out, err};
  std::optional<RobotModel> robot = loadFromFile(config.urdf_path, output);
  if (!config.urdf_path.empty() && !robot) return programs::kExitBadArguments;
  const std::unique_ptr<lcm::LCM> lcm = programs::openLcmOrReport(config.lcm_url, kProgram, err);
  if (!lcm) return programs::kExitBadArguments;
  const auto run_start = std::chrono::steady_clock::now();
  const auto run_time =
      std::chrono::duration_cast<Duration>(std::chrono::duration<double>(config.duration));
  if (!robot) {
    robot = waitForDescription(*lcm, config.description_channel, config.description_request_channel,
                               config.authority, stop, output, run_time);
    if (!robot) return stop ? 0 : 1;
  }
  std::optional<JointStateGenerator> generator;
  try {
    generator.emplace(*robot, config.generator);
  } catch (const std::invalid_argument& e) {
    output.complain(std::string("--position: ") + e.what());
    return programs::kExitBadArguments;
  }
  if (generator->jointNames().empty()) {
    output.complain("robot '" + robot->name +
                    "' has no movable joint that follows no other: no joint states to publish");
    return 1;
  }
  const std::size_t mimics = generator->mimicCount();
  output.say(std::to_string(generator->jointNames().size() - mimics) + " joints of robot '" +
             robot->name + "' " + (config.generator.sweep ? "sweeping" : "at rest") + ", " +
             programs::formatNumber(config.rate) + " joint states per second on " + config.channel +
             " via '" + programs::describeLcmUrl(config.lcm_url) + "'" +
             (mimics == 0 ? std::string()
                          : "; " + std::to_string(mimics) + " mimic joint" +
                                (mimics == 1 ? " follows" : "s follow") + " them"));

  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / config.rate));
  const auto start = std::chrono::steady_clock::now();
  const auto end = run_start + run_time;
  auto next = start;
  std::uint64_t published = 0;
  std::uint64_t failed = 0;
  BatchNumbering numbering(config.channel, config.authority);
  const JointStateSources sources(*lcm, config.sources, generator->jointNames());
  while (!stop && (config.duration <= 0.0 || std::chrono::steady_clock::now() < end)) {
    const auto elapsed = std::chrono::steady_clock::now() - start;
    joint_state_t state = generator->stateAt(std::chrono::duration<double>(elapsed).count(), now(),
                                             sources.positions());
    state.authority = config.authority;
    state.sequence = numbering.next();
    (lcm->publish(config.channel, &state) == 0 ? published : failed) += 1;
    next += period;
    const auto now_steady = std::chrono::steady_clock::now();
    if (next + period < now_steady) next = now_steady;  // fell behind: keep the rate, not the count
    if (!handleUntil(*lcm, config.duration > 0.0 ? std::min(next, end) : next, stop)) {
      output.complain("LCM stopped working at '" + programs::describeLcmUrl(config.lcm_url) + "'");
      return programs::kExitFailure;
    }
  }
  output.say("stopped after " + std::to_string(published) + " joint states" +
             (failed != 0 ? ", " + std::to_string(failed) + " failed to publish" : ""));
  return 0;
}

int jointPublisherMain(int argc, char** argv) {
  const auto parsed =
      parseJointPublisherCommandLine(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed.config) {
    (parsed.exit_code == 0 ? std::cout : std::cerr) << parsed.message;
    return parsed.exit_code;
  }
  return runJointPublisher(*parsed.config, programs::installStopSignalHandlers(), std::cout,
                           std::cerr);
}

}  // namespace lcmtf::urdf
