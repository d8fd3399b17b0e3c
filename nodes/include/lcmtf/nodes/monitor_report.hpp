#pragma once

#include <string>

#include "lcmtf/nodes/chain_delay.hpp"
#include "lcmtf/nodes/tf_traffic.hpp"

namespace lcmtf::nodes {

/// lcmtf-monitor's report: what was heard from `source` ("TF and TF_STATIC at URL"), the
/// chain and its net delay when `chain` is given, then frames (as a tree), authorities,
/// conflicts and problems. Rates in Hz, delays in milliseconds.
std::string formatMonitorReport(const TrafficSummary& summary, const std::string& source,
                                const ChainReport* chain);

}  // namespace lcmtf::nodes
