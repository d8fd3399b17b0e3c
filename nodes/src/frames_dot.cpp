#include "lcmtf/nodes/frames_dot.hpp"

#include <set>
#include <sstream>

#include "lcmtf/nodes/pose_text.hpp"

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

// Length of the well-formed UTF-8 sequence at `at`, or 0 (Graphviz's renderers fail on
// malformed UTF-8, and names come from the network).
std::size_t utf8SequenceLength(const std::string& text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // allowed range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  }
  if (length == 0 || at + length > text.size()) return 0;
  if (byte(at + 1) < low || byte(at + 1) > high) return 0;
  for (std::size_t i = at + 2; i < at + length; ++i) {
    if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
  }
  return length;
}

}  // namespace

std::string dotQuoted(const std::string& text) {
  std::string quoted = "\"";
  for (std::size_t at = 0; at < text.size(); ++at) {
    const char c = text[at];
    if (static_cast<unsigned char>(c) >= 0x80) {
      const std::size_t length = utf8SequenceLength(text, at);
      quoted += length ? text.substr(at, length) : "?";
      at += length ? length - 1 : 0;
    } else if (c == '\n') {
      quoted += "\\n";
    } else if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      quoted += '?';
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

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
    dot << "  " << dotQuoted(frame) << " [label=" << dotQuoted(frame)
        << (conflicted.count(frame) ? ", color=red, fontcolor=red" : "") << "];\n";
  }
  for (const EdgeTraffic& edge : summary.edges) {
    dot << "  " << dotQuoted(edge.parent) << " -> " << dotQuoted(edge.child)
        << " [label=" << dotQuoted(edgeLabel(edge, summary.window_end));
    if (edge.is_static) dot << ", style=dashed";
    if (conflicted.count(edge.child)) dot << ", color=red, fontcolor=red";
    dot << "];\n";
  }
  dot << "}\n";
  return dot.str();
}

}  // namespace lcmtf::nodes
