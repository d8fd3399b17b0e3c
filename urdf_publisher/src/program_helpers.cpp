#include "program_helpers.hpp"

#include "lcmtf/printable.hpp"
#include "lcmtf/programs/number_text.hpp"
#include "lcmtf_urdf/robot_description.hpp"

namespace lcmtf::urdf {

void ProgramOutput::say(const std::string& message) const {
  out << program << ": " << terminalSafe(message) << std::endl;
}

void ProgramOutput::complain(const std::string& message) const {
  err << program << ": " << terminalSafe(message) << std::endl;
}

std::function<void(const std::string&)> ProgramOutput::reporter() const {
  return [this](const std::string& message) { complain(message); };
}

std::optional<RobotModel> loadFromFile(const std::string& path, const ProgramOutput& output) {
  if (path.empty()) return std::nullopt;
  try {
    return loadRobotModel(path);
  } catch (const UrdfError& e) {
    output.complain(e.what());
    return std::nullopt;
  }
}

std::optional<RobotModel> waitForDescription(lcm::LCM& lcm, const std::string& channel,
                                             const std::string& request_channel,
                                             const std::string& authority,
                                             const std::atomic<bool>& stop,
                                             const ProgramOutput& output, Duration timeout) {
  DescriptionWaitOptions options;
  options.timeout = timeout;
  options.channel = channel;
  options.request_channel = request_channel;
  options.authority = authority;
  options.reporter = output.reporter();
  output.say("no URDF file given: waiting for a robot description on " + channel + " (asking on " +
             request_channel + ")");
  DescriptionWaitStatistics heard;
  std::optional<RobotModel> robot = waitForRobotDescription(lcm, options, stop, &heard);
  if (heard.refused != 0) {
    output.say("refused " + std::to_string(heard.refused) + " of the " +
               std::to_string(heard.received) + " robot descriptions heard on " + channel);
  }
  if (!robot && !stop) {
    output.complain("no valid robot description heard on " + channel + " within " +
                    programs::formatNumber(std::chrono::duration<double>(timeout).count()) + " s");
  }
  return robot;
}

}  // namespace lcmtf::urdf
