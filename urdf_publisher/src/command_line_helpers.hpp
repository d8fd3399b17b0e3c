#pragma once

#include <CLI/CLI.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/programs/program_authority.hpp"
#include "lcmtf_urdf/command_line.hpp"

namespace lcmtf::urdf {

/// Where a program gets its robot and LCM, and how it signs what it sends.
struct RobotSourceArguments {
  std::string& urdf_path;
  std::string& lcm_url;
  std::string& description_channel;
  std::string& description_request_channel;
  std::string& authority;
};

/// The options every program of urdf_publisher/ takes to find its robot and LCM.
void addRobotSourceOptions(CLI::App& app, const RobotSourceArguments& arguments);

/// Parses `arguments` (without the program name) with `app`; fills `parsed` with the exit
/// code and the help, version or error text when the program should not run.
template <class Config>
bool parseWith(CLI::App& app, const std::vector<std::string>& arguments,
               ParsedCommandLine<Config>& parsed) {
  std::ostringstream out;
  std::ostringstream err;
  const std::optional<int> status = programs::parseCommandLine(app, arguments, out, err);
  if (!status) return true;
  parsed.exit_code = *status;
  parsed.message = out.str() + err.str();
  return false;
}

/// A wrong command line found after parsing, reported as parseWith reports one; false.
template <class Config>
bool refuse(const CLI::App& app, const std::string& message, ParsedCommandLine<Config>& parsed) {
  std::ostringstream err;
  parsed.exit_code = programs::reportBadArguments(app, message, err);
  parsed.message = err.str();
  return false;
}

}  // namespace lcmtf::urdf
