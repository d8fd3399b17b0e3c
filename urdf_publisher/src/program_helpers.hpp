#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/time.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// Where a program's messages go, each line starting with the program's name.
struct ProgramOutput {
  const char* program;
  std::ostream& out;
  std::ostream& err;

  void say(const std::string& message) const;
  void complain(const std::string& message) const;
  /// complain() as a reporter for the processor and the description wait.
  std::function<void(const std::string&)> reporter() const;
};

/// The robot in `path`; nothing when `path` is empty or (said on err) cannot be used.
std::optional<RobotModel> loadFromFile(const std::string& path, const ProgramOutput& output);

/// waitForRobotDescription, saying what it waits for; nothing when stopped first or, with a
/// `timeout` above zero, when none came within it (also said on err).
std::optional<RobotModel> waitForDescription(lcm::LCM& lcm, const std::string& channel,
                                             const std::string& request_channel,
                                             const std::string& authority,
                                             const std::atomic<bool>& stop,
                                             const ProgramOutput& output,
                                             Duration timeout = Duration::zero());

}  // namespace lcmtf::urdf
