#pragma once

#include <string>

#include "lcmtf/nodes/tf_traffic.hpp"

namespace lcmtf::nodes {

/// The frames heard as a Graphviz digraph captioned `caption`: edges labelled with broadcaster,
/// rate, newest stamp and age, buffer span; static edges dashed, conflicted frames red.
std::string framesToDot(const TrafficSummary& summary, const std::string& caption);

}  // namespace lcmtf::nodes
