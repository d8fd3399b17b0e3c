#pragma once

#include <atomic>
#include <chrono>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lcmtf/channels.hpp"
#include "lcmtf/nodes/program_support.hpp"
#include "lcmtf/transform_listener.hpp"

namespace lcmtf::nodes {

/// The LCM URL and channels a tool talks on.
struct TfConnection {
  std::string lcm_url;  ///< "" is LCM's default (LCM_DEFAULT_URL or udpm ttl=0)
  std::string tf_channel = kTfChannel;
  std::string static_channel = kTfStaticChannel;
  std::string request_channel = kTfStaticRequestChannel;
  double max_stamp_ahead_s = toSeconds(kDefaultMaxStampAhead);  ///< for a listener's buffer
};

/// Adds --lcm-url, --static-channel, --request-channel and, when `with_dynamic`, --tf-channel.
void addConnectionOptions(CLI::App& app, TfConnection& connection, bool with_dynamic = true);

/// What the main of a tool that listens does: `parse` the command line, open the LCM of
/// options.connection, then `run`. Returns the exit status.
template <class Options>
int parseOpenAndRun(const std::vector<std::string>& args, const std::string& program,
                    std::ostream& out, std::ostream& err, const std::atomic<bool>& stop,
                    std::optional<int> (*parse)(const std::vector<std::string>&, Options&,
                                                std::ostream&, std::ostream&),
                    int (*run)(const Options&, lcm::LCM&, std::ostream&, std::ostream&,
                               const std::atomic<bool>&)) {
  Options options;
  if (const std::optional<int> status = parse(args, options, out, err)) return *status;
  const std::unique_ptr<lcm::LCM> lcm = openLcmOrReport(options.connection.lcm_url, program, err);
  if (!lcm) return kExitBadArguments;
  return run(options, *lcm, out, err, stop);
}

/// What the transforms `listener` refused as stamped ahead of this machine's clock (none: "")
/// mean for a tool's user, who may give --max-stamp-ahead.
std::string stampedAheadNote(const TransformListener& listener, const TfConnection& connection);

/// Listener options for the connection's channels, signed by `program`, refusals not reported.
ListenerOptions listenerOptionsFor(const TfConnection& connection, const std::string& program);

}  // namespace lcmtf::nodes
