#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "lcmtf/channels.hpp"
#include "lcmtf_urdf/command_line.hpp"

namespace lcmtf::urdf {

/// A number in [lower, upper]; unlike CLI::Range it also refuses NaN and infinities.
inline CLI::Validator finiteNumberIn(double lower, double upper) {
  std::ostringstream description;
  description << "NUMBER in [" << lower << ", " << upper << "]";
  return CLI::Validator(
      [lower, upper](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value)) {
          return "'" + text + "' is not a finite number";
        }
        if (value < lower || value > upper) {
          std::ostringstream out;
          out << text << " is outside [" << lower << ", " << upper << "]";
          return out.str();
        }
        return std::string();
      },
      description.str());
}

/// "program@host:pid" with the program's whole name (the kernel's short name may be cut).
inline std::string programAuthority(const std::string& program) {
  const std::string authority = defaultAuthority();
  return program + authority.substr(authority.find('@'));
}

/// Where a program gets its robot and LCM, and how it signs what it sends.
struct RobotSourceArguments {
  std::string& urdf_path;
  std::string& lcm_url;
  std::string& description_channel;
  std::string& description_request_channel;
  std::string& authority;
};

/// The options every program of urdf_publisher/ takes to find its robot and LCM.
inline void addRobotSourceOptions(CLI::App& app, const RobotSourceArguments& arguments) {
  app.add_option("urdf", arguments.urdf_path,
                 "The robot's URDF file; without it, the first valid description on "
                 "--description-channel is used");
  app.add_option("--lcm-url", arguments.lcm_url,
                 "LCM URL (default: LCM's, which stays on this host)");
  app.add_option("--description-channel", arguments.description_channel)->capture_default_str();
  app.add_option("--description-request-channel", arguments.description_request_channel)
      ->capture_default_str();
  arguments.authority = programAuthority(app.get_name());
  app.add_option("--authority", arguments.authority,
                 "Names this program in what it sends (default: program@host:pid)");
}

/// Parses `arguments` (without the program name) with `app`; fills `parsed` with the exit
/// code and CLI11's help or error text when the program should not run.
template <class Config>
bool parseWith(CLI::App& app, const std::vector<std::string>& arguments,
               ParsedCommandLine<Config>& parsed) {
  std::vector<std::string> storage{app.get_name()};
  storage.insert(storage.end(), arguments.begin(), arguments.end());
  std::vector<const char*> argv;
  for (const std::string& argument : storage) argv.push_back(argument.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    return true;
  } catch (const CLI::ParseError& error) {
    std::ostringstream out;
    std::ostringstream err;
    parsed.exit_code = app.exit(error, out, err) == 0 ? 0 : 2;
    parsed.message = out.str() + err.str();
    return false;
  }
}

}  // namespace lcmtf::urdf
