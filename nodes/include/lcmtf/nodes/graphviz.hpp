#pragma once

#include <chrono>
#include <optional>
#include <string>

namespace lcmtf::nodes {

/// The path of the executable `program` in a directory of $PATH, if there is one.
std::optional<std::string> findOnPath(const std::string& program);

/// Runs Graphviz `dot` to draw `dot_file` as `format` ("pdf", "svg") into `output`. Returns an
/// empty string on success, otherwise what went wrong. `dot` is killed after `timeout`.
std::string renderDot(const std::string& dot_program, const std::string& dot_file,
                      const std::string& format, const std::string& output,
                      std::chrono::seconds timeout = std::chrono::seconds(60));

}  // namespace lcmtf::nodes
