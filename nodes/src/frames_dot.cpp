#include "lcmtf/nodes/frames_dot.hpp"

#include <set>
#include <sstream>

#include "lcmtf/nodes/pose_text.hpp"
#include "lcmtf/printable.hpp"

namespace lcmtf::nodes {

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// "most recent: <time> (<age> s old)", the age as of `heard_until`.
std::string mostRecentLine(TimePoint time, TimePoint heard_until) {
  return "most recent: " + toString(time) + " (" + fixedDecimals(toSeconds(heard_until - time), 3) +
         " s old)\n";
}

// Lines joined with newlines that dotQuoted turns into Graphviz's centred line breaks.
std::string edgeLabel(const EdgeTraffic& edge, TimePoint heard_until) {
  const bool several = edge.authorities.size() > 1;
  std::string label = edge.is_static ? "static\n" : "";
  label += (several ? "broadcasters: " : "broadcaster: ") + joined(edge.authorities) + "\n";
  if (several) label += "CONFLICT: more than one broadcaster\n";
  if (edge.is_static) {
    label += edge.samples < 2 ? std::string("resent: - (heard once)\n")
                              : "resent: " + fixedDecimals(edge.rate_hz, 2) + " Hz (heard " +
                                    std::to_string(edge.samples) + " times)\n";
    label += mostRecentLine(edge.last_received, heard_until);
    return label + "buffer: one value, valid at every time";
  }
  label += edge.samples < 2 ? std::string("average rate: - (heard once)\n")
                            : "average rate: " + fixedDecimals(edge.rate_hz, 2) + " Hz\n";
  label += mostRecentLine(edge.newest_stamp, heard_until);
  label += "buffer: " + fixedDecimals(toSeconds(edge.newest_stamp - edge.oldest_stamp), 3) +
           " s (" + std::to_string(edge.buffered) + " samples)";
  return label;
}

// dotQuoted alone shows every unshowable byte as '?', which would merge frames that differ
// only there; printable's escapes keep every name's node its own.
std::string nodeId(const std::string& frame) { return dotQuoted(printable(frame)); }

}  // namespace

std::string framesToDot(const TrafficSummary& summary, const std::string& caption) {
  std::set<std::string> frames;
  std::set<std::string> conflicted;
  for (const EdgeTraffic& edge : summary.edges) {
    frames.insert(edge.parent);
    frames.insert(edge.child);
  }
  for (const FrameConflict& conflict : summary.conflicts) conflicted.insert(conflict.child);

  std::ostringstream dot;
  dot << "digraph lcmtf_frames {\n"
      << "  graph [charset=\"UTF-8\", rankdir=TB, labelloc=b, fontsize=11, label="
      << dotQuoted(caption) << "];\n"
      << "  node [shape=box, style=rounded, fontsize=12];\n"
      << "  edge [fontsize=9];\n";
  for (const std::string& frame : frames) {
    dot << "  " << nodeId(frame) << " [label=" << dotQuoted(frame)
        << (conflicted.count(frame) ? ", color=red, fontcolor=red" : "") << "];\n";
  }
  for (const EdgeTraffic& edge : summary.edges) {
    dot << "  " << nodeId(edge.parent) << " -> " << nodeId(edge.child)
        << " [label=" << dotQuoted(edgeLabel(edge, summary.window_end));
    if (edge.is_static) dot << ", style=dashed";
    if (conflicted.count(edge.child)) dot << ", color=red, fontcolor=red";
    dot << "];\n";
  }
  dot << "}\n";
  return dot.str();
}

}  // namespace lcmtf::nodes
