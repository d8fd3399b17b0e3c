#pragma once

#include <atomic>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/nodes/tf_connection.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/time.hpp"

namespace lcmtf::nodes {

/// Which instant lcmtf-echo looks up: the latest data, a fixed instant, or a while before now.
struct EchoTime {
  enum class Kind { kLatest, kFixed, kBeforeNow } kind = Kind::kLatest;
  TimePoint fixed;
  Duration before_now{};

  /// The instant to look up when the clock reads `now` (kLatestTime for the latest data).
  TimePoint at(TimePoint now) const;
};

/// `text` as --time reads it: seconds since the Unix epoch, 0 for the latest data, or a
/// negative number of seconds before now. CommandLineError otherwise.
EchoTime parseEchoTime(const std::string& text);

/// How long --once waits for a pose unless --timeout says otherwise.
inline constexpr Duration kOnceTimeout = std::chrono::seconds(5);

/// What lcmtf-echo prints, how often and for how long.
struct EchoOptions {
  TfConnection connection;
  std::string reference_frame;
  std::string frame;
  double rate_hz = 1.0;
  EchoTime time;
  bool once = false;
  int precision = 3;
  std::optional<Duration> timeout;  ///< give up when no pose could be printed by then
};

/// Reads the command line into `options`; the exit status when the tool must not run.
std::optional<int> parseEchoCommandLine(const std::vector<std::string>& args, EchoOptions& options,
                                        std::ostream& out, std::ostream& err);

/// Why `reference_frame` <- `frame` cannot be looked up yet, naming what is missing.
std::string describeMissing(const BufferCore& buffer, const std::string& reference_frame,
                            const std::string& frame, TimePoint time, bool heard_anything);

/// Listens on `lcm` and prints the pose at the rate until `stop` (or once); returns the exit
/// status. Waiting notes go to `err`.
int runEcho(const EchoOptions& options, lcm::LCM& lcm, std::ostream& out, std::ostream& err,
            const std::atomic<bool>& stop);

/// The whole program: parse, open LCM, run.
int echoCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                const std::atomic<bool>& stop);

}  // namespace lcmtf::nodes
