#pragma once

#include <optional>
#include <string>

namespace lcmtf::urdf {

/// A command line read: the configuration to run with, or the exit code and the text to show
/// (help on stdout with code 0, an error naming the bad argument on stderr otherwise).
template <class Config>
struct ParsedCommandLine {
  std::optional<Config> config;
  int exit_code = 0;
  std::string message;
};

}  // namespace lcmtf::urdf
