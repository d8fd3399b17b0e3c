#pragma once

#include <atomic>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "lcmtf/nodes/tf_connection.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf::nodes {

/// What lcmtf-static-publisher publishes, where, and how often.
struct StaticPublisherOptions {
  TfConnection connection;
  std::vector<TransformStamped> transforms;
  std::string authority;
  Duration resend_period = std::chrono::seconds(1);  ///< zero: only at start and on request
  bool check_only = false;                           ///< print the transforms, publish nothing
};

/// Reads the flag form, the two positional forms and --file into `options`. Returns the exit
/// status when the tool must not run (help, version, a bad argument reported on `err`).
std::optional<int> parseStaticPublisherCommandLine(const std::vector<std::string>& args,
                                                   StaticPublisherOptions& options,
                                                   std::ostream& out, std::ostream& err);

/// Publishes the transforms, answers requests and resends them until `stop` is set.
int runStaticPublisher(const StaticPublisherOptions& options, std::ostream& out, std::ostream& err,
                       const std::atomic<bool>& stop);

/// The whole program: parse, then run.
int staticPublisherCommand(const std::vector<std::string>& args, std::ostream& out,
                           std::ostream& err, const std::atomic<bool>& stop);

/// One line for a transform: "parent -> child: translation [...], rotation xyzw [...] ...".
std::string describeStaticTransform(const TransformStamped& transform);

}  // namespace lcmtf::nodes
