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

#include "lcmtf/nodes/command_line.hpp"
#include "lcmtf/transform_listener.hpp"

namespace lcmtf::nodes {

/// The LCM URL and channels a tool talks on.
struct TfConnection {
  std::string lcm_url;  ///< "" is LCM's default (LCM_DEFAULT_URL or udpm ttl=0)
  std::string tf_channel = "TF";
  std::string static_channel = "TF_STATIC";
  std::string request_channel = "TF_STATIC_REQUEST";
};

/// Adds --lcm-url, --static-channel, --request-channel and, when `with_dynamic`, --tf-channel.
void addConnectionOptions(CLI::App& app, TfConnection& connection, bool with_dynamic = true);

/// The URL an LCM opened on `lcm_url` uses, spelled out for messages.
std::string describeLcmUrl(const std::string& lcm_url);

/// An LCM on the connection's URL; CommandLineError naming --lcm-url when it cannot be opened.
std::unique_ptr<lcm::LCM> openLcm(const TfConnection& connection);

/// openLcm, with a failure reported on `err` as "program: message"; null when it failed.
std::unique_ptr<lcm::LCM> openLcmOrReport(const TfConnection& connection,
                                          const std::string& program, std::ostream& err);

/// lcm.handleTimeout that takes a wait cut short by a signal as nothing handled. Returns
/// false only when LCM itself fails; `handled` says whether a message was dispatched.
bool handleLcmFor(lcm::LCM& lcm, std::chrono::milliseconds timeout, bool* handled = nullptr);

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
  const std::unique_ptr<lcm::LCM> lcm = openLcmOrReport(options.connection, program, err);
  if (!lcm) return kExitBadArguments;
  return run(options, *lcm, out, err, stop);
}

/// Listener options for the connection's channels, signed by `program`, refusals not reported.
ListenerOptions listenerOptionsFor(const TfConnection& connection, const std::string& program);

}  // namespace lcmtf::nodes
