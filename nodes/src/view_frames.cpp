#include "lcmtf/nodes/view_frames.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/nodes/frames_dot.hpp"
#include "lcmtf/nodes/graphviz.hpp"
#include "lcmtf/nodes/pose_text.hpp"
#include "lcmtf/nodes/tf_traffic_subscriber.hpp"
#include "lcmtf/printable.hpp"

namespace lcmtf::nodes {

namespace {

constexpr const char* kProgram = "lcmtf-view-frames";

constexpr const char* kDescription =
    "Listens to the transform channels for --wait seconds and draws the frame tree: "
    "OUTPUT.gv in Graphviz's DOT language and, when Graphviz is installed, OUTPUT.pdf and "
    "OUTPUT.svg. Each edge parent -> child shows who broadcast it, its average rate, its most "
    "recent stamp and how old that was, and how much history a listener's buffer holds. "
    "Static edges are dashed; a frame sent by more than one broadcaster is red.";

constexpr const char* kExamples =
    "Examples:\n"
    "  lcmtf-view-frames                          writes frames.gv, frames.pdf, frames.svg\n"
    "  lcmtf-view-frames --wait 2 --output /tmp/robot_tree\n"
    "  lcmtf-view-frames --dot-only && dot -Tpng frames.gv -o frames.png";

// "again.gv" names the same files as "again": the extension of one of them is not kept.
std::string withoutDrawingExtension(const std::string& path) {
  for (const char* extension : {".gv", ".dot", ".pdf", ".svg"}) {
    const std::string suffix = extension;
    const bool ends_so = path.size() > suffix.size() &&
                         path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0 &&
                         path[path.size() - suffix.size() - 1] != '/';
    if (ends_so) return path.substr(0, path.size() - suffix.size());
  }
  return path;
}

// A folder, named as one or already there, gets frames.gv, frames.pdf and frames.svg.
std::string outputStem(const std::string& path) {
  std::error_code error;
  if (path.back() == '/' || std::filesystem::is_directory(path, error)) {
    return (std::filesystem::path(path) / kDefaultStem).string();
  }
  return withoutDrawingExtension(path);
}

std::string plural(std::size_t count, const std::string& word) {
  return std::to_string(count) + " " + word + (count == 1 ? "" : "s");
}

}  // namespace

std::optional<int> parseViewFramesCommandLine(const std::vector<std::string>& args,
                                              ViewFramesOptions& options, std::ostream& out,
                                              std::ostream& err) {
  auto app = makeToolApp(kProgram, kDescription, kExamples);
  double wait_seconds = 5.0;
  bool dot_only = false;
  app->add_option("--wait", wait_seconds, "Seconds to listen before drawing")
      ->check(positiveFiniteNumberUpTo(3600.0))
      ->type_name("SECONDS")
      ->capture_default_str();
  app->add_option("-o,--output", options.output,
                  "Path of the files, with or without an extension; .gv, .pdf, .svg are put "
                  "in place of the extension. A folder gets frames.gv, frames.pdf, frames.svg")
      ->check(nonEmptyName())
      ->type_name("PATH")
      ->capture_default_str();
  app->add_flag("--dot-only", dot_only, "Write only the .gv file, even with Graphviz installed");
  addConnectionOptions(*app, options.connection);
  if (auto status = parseCommandLine(*app, args, out, err)) return status;
  options.output = outputStem(options.output);
  options.wait = secondsToDuration(wait_seconds);
  options.render = !dot_only;
  return std::nullopt;
}

int runViewFrames(const ViewFramesOptions& options, lcm::LCM& lcm, std::ostream& out,
                  std::ostream& err, const std::atomic<bool>& stop) {
  const std::string dot_file = options.output + ".gv";
  std::ofstream dot_stream(dot_file, std::ios::trunc);
  if (!dot_stream) {  // found before listening, not after
    err << kProgram << ": --output: cannot write '" << dot_file << "': " << std::strerror(errno)
        << '\n';
    return kExitBadArguments;
  }
  const std::string source = options.connection.tf_channel + " and " +
                             options.connection.static_channel + " at " +
                             describeLcmUrl(options.connection.lcm_url);
  out << "Listening to " << source << " for " << fixedDecimals(toSeconds(options.wait), 1)
      << " s..." << std::endl;

  // Answers to the request may be stamped before the call that sends it returns.
  const TimePoint start = now();
  TfTraffic traffic;
  TfTrafficSubscriber subscriber(lcm, options.connection, traffic);
  subscriber.requestStatics(programAuthority(kProgram));
  const auto deadline = std::chrono::steady_clock::now() + options.wait;
  while (!stop.load() && std::chrono::steady_clock::now() < deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (!handleLcmFor(lcm, std::min(left, std::chrono::milliseconds(50)))) {
      err << kProgram << ": LCM stopped working at " << source << '\n';
      return kExitFailure;
    }
  }
  const TimePoint end = now();
  const TrafficSummary summary = traffic.summarize(start, end, BufferCore::kDefaultCacheTime);
  const std::string caption = "lcmtf frames heard on " + source + " for " +
                              fixedDecimals(toSeconds(end - start), 1) + " s, up to " +
                              toString(end);
  dot_stream << framesToDot(summary, caption);
  dot_stream.close();
  if (!dot_stream) {
    err << kProgram << ": could not finish writing '" << dot_file << "'\n";
    return kExitFailure;
  }

  std::size_t statics = 0;
  for (const EdgeTraffic& edge : summary.edges) statics += edge.is_static ? 1 : 0;
  out << "Heard " << plural(summary.edges.size(), "edge") << " (" << statics << " static) from "
      << plural(summary.authorities.size(), "broadcaster") << ", "
      << plural(summary.conflicts.size(), "conflict") << ".\n"
      << "Wrote " << dot_file << '\n';
  for (const std::string& problem : summary.problems)
    out << "Problem: " << printable(problem) << '\n';

  int status = kExitSuccess;
  if (options.render) {
    const std::optional<std::string> dot = findOnPath("dot");
    if (!dot) {
      out << "Graphviz's dot is not on PATH (apt-get install graphviz): no PDF or SVG drawn.\n";
    }
    for (const char* format : {"pdf", "svg"}) {
      if (!dot) break;
      const std::string drawing = options.output + "." + format;
      const std::string failure = renderDot(*dot, dot_file, format, drawing);
      if (failure.empty()) {
        out << "Wrote " << drawing << '\n';
      } else {
        err << kProgram << ": " << failure << '\n';
        status = kExitFailure;
      }
    }
  }
  out << std::flush;
  if (summary.messages == 0 && summary.malformed == 0) {
    err << kProgram << ": nothing heard on " << source
        << "; is a broadcaster running on that URL and those channels?\n";
    return kExitFailure;
  }
  return status;
}

int viewFramesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                      const std::atomic<bool>& stop) {
  return parseOpenAndRun(args, kProgram, out, err, stop, &parseViewFramesCommandLine,
                         &runViewFrames);
}

}  // namespace lcmtf::nodes
