#pragma once

#include <string>

#include "lcmtf/nodes/tf_traffic.hpp"

namespace lcmtf::nodes {

/// The frames heard as a Graphviz digraph, `caption` under it. Each edge parent -> child says
/// who broadcast it, its average rate, its newest stamp and age, and the history a buffer
/// holds; static edges are dashed, frames sent by two authorities drawn red.
std::string framesToDot(const TrafficSummary& summary, const std::string& caption);

/// `text` as a quoted DOT string that Graphviz shows as it is; control characters and
/// malformed UTF-8 become '?'.
std::string dotQuoted(const std::string& text);

}  // namespace lcmtf::nodes
