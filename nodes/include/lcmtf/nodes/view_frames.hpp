#pragma once

#include <atomic>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/nodes/tf_connection.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/time.hpp"

namespace lcmtf::nodes {

/// Where lcmtf-view-frames writes unless told, and what it calls the files in a folder it is given.
constexpr const char* kDefaultStem = "frames";

/// How long lcmtf-view-frames listens and where it writes the tree.
struct ViewFramesOptions {
  TfConnection connection;
  Duration wait = std::chrono::seconds(5);
  std::string output = kDefaultStem;  ///< writes output.gv, and output.pdf and output.svg
  bool render = true;                 ///< draw PDF and SVG when Graphviz's dot is on PATH
};

/// Reads the command line into `options`; the exit status when the tool must not run.
std::optional<int> parseViewFramesCommandLine(const std::vector<std::string>& args,
                                              ViewFramesOptions& options, std::ostream& out,
                                              std::ostream& err);

/// Listens on `lcm` for options.wait (or until `stop`), then writes the files and prints
/// their names. Returns the exit status (1 when nothing was heard or drawing failed).
int runViewFrames(const ViewFramesOptions& options, lcm::LCM& lcm, std::ostream& out,
                  std::ostream& err, const std::atomic<bool>& stop);

/// The whole program: parse, open LCM, run.
int viewFramesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                      const std::atomic<bool>& stop);

}  // namespace lcmtf::nodes
