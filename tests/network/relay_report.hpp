#pragma once

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace lcmtf_test {

/// What the lossy relay did with the datagrams that arrived on one of its interfaces.
struct RelayCounts {
  std::string arrived_on;
  std::uint64_t received = 0;
  std::uint64_t forwarded = 0;  ///< sent on the other interface, at once or after a while
  std::uint64_t dropped = 0;
  std::uint64_t reordered = 0;  ///< forwarded after a datagram that arrived later
};

/// The relay's report: a line "INTERFACE received R forwarded F dropped D reordered O" each.
inline std::string formatRelayReport(const std::vector<RelayCounts>& report) {
  std::ostringstream text;
  for (const RelayCounts& counts : report) {
    text << counts.arrived_on << " received " << counts.received << " forwarded "
         << counts.forwarded << " dropped " << counts.dropped << " reordered " << counts.reordered
         << '\n';
  }
  return text.str();
}

/// The counts formatRelayReport wrote; lines it cannot read are left out.
inline std::vector<RelayCounts> parseRelayReport(const std::string& text) {
  std::vector<RelayCounts> report;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    RelayCounts counts;
    std::string received, forwarded, dropped, reordered;
    if (fields >> counts.arrived_on >> received >> counts.received >> forwarded >>
        counts.forwarded >> dropped >> counts.dropped >> reordered >> counts.reordered) {
      report.push_back(counts);
    }
  }
  return report;
}

}  // namespace lcmtf_test
