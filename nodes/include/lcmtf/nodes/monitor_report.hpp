#pragma once

#include <string>

#include "lcmtf/nodes/chain_delay.hpp"
#include "lcmtf/nodes/tf_traffic.hpp"

namespace lcmtf::nodes {

/// lcmtf-monitor's report on what `source` carried: the chain (when given) and its net delay,
/// frames as a tree, authorities, conflicts, problems. Rates in Hz, delays in milliseconds.
/// Names are escaped as printable() does, so the report is safe to print as it is.
std::string formatMonitorReport(const TrafficSummary& summary, const std::string& source,
                                const ChainReport* chain);

}  // namespace lcmtf::nodes
