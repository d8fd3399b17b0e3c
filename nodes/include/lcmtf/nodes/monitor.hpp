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

/// What lcmtf-monitor watches and for how long.
struct MonitorOptions {
  TfConnection connection;
  std::string frame_a;  ///< with frame_b: report the chain between them; both empty: none
  std::string frame_b;
  Duration duration = std::chrono::seconds(5);  ///< one report after this; or each window
  bool continuous = false;                      ///< a fresh report every `duration` until stopped
  bool clear_screen = false;  ///< before each continuous report (when printing to a terminal)
};

/// Reads the command line into `options`; the exit status when the tool must not run.
std::optional<int> parseMonitorCommandLine(const std::vector<std::string>& args,
                                           MonitorOptions& options, std::ostream& out,
                                           std::ostream& err);

/// Listens on `lcm` and prints the report after each window; returns the exit status (1 when
/// a single window heard nothing, or no chain between the two frames asked about).
int runMonitor(const MonitorOptions& options, lcm::LCM& lcm, std::ostream& out, std::ostream& err,
               const std::atomic<bool>& stop);

/// The whole program: parse, open LCM, run.
int monitorCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                   const std::atomic<bool>& stop);

}  // namespace lcmtf::nodes
