#include "lcmtf/nodes/monitor_report.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "lcmtf/nodes/pose_text.hpp"
#include "lcmtf/nodes/text_table.hpp"
#include "lcmtf/printable.hpp"

namespace lcmtf::nodes {

namespace {

// Every name and description from the network escaped before the tables measure their
// columns: escaping after would misalign them, and a newline kept would forge rows.
void escapeAll(std::string& text) { text = printable(text); }
void escapeAll(std::vector<std::string>& texts) {
  for (std::string& text : texts) escapeAll(text);
}

TrafficSummary shownSafely(TrafficSummary summary) {
  for (EdgeTraffic& edge : summary.edges) {
    escapeAll(edge.parent);
    escapeAll(edge.child);
    escapeAll(edge.authorities);
  }
  for (AuthorityTraffic& authority : summary.authorities) {
    escapeAll(authority.authority);
    escapeAll(authority.frames);
  }
  for (FrameConflict& conflict : summary.conflicts) {
    escapeAll(conflict.child);
    escapeAll(conflict.senders);
  }
  escapeAll(summary.problems);
  return summary;
}

ChainReport shownSafely(ChainReport chain) {
  escapeAll(chain.frame_a);
  escapeAll(chain.frame_b);
  escapeAll(chain.frames);
  escapeAll(chain.problem);
  return chain;
}

std::string rate(double hz) { return hz > 0.0 ? fixedDecimals(hz, 2) : "-"; }
std::string milliseconds(double seconds) { return fixedDecimals(seconds * 1e3, 3); }

std::string joined(const std::vector<std::string>& items, const std::string& separator,
                   std::size_t at_most = 0) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (at_most && i == at_most) return text + " (+" + std::to_string(items.size() - i) + ")";
    text += (i ? separator : "") + items[i];
  }
  return text;
}

// Edges depth first from the roots (frames that are nobody's child), children by name, so
// that indenting each child by its depth draws the tree. A frame with several parents is
// expanded below the edge heard most; its other edges stay leaves. Edges in a loop come last.
std::vector<std::pair<const EdgeTraffic*, int>> treeOrder(const std::vector<EdgeTraffic>& edges) {
  std::map<std::string, std::vector<const EdgeTraffic*>> children_of;
  std::map<std::string, const EdgeTraffic*> main_edge_of;
  for (const EdgeTraffic& edge : edges) {
    children_of[edge.parent].push_back(&edge);
    const EdgeTraffic*& main_edge = main_edge_of[edge.child];
    if (!main_edge || edge.samples > main_edge->samples) main_edge = &edge;
  }
  std::vector<std::pair<const EdgeTraffic*, int>> order;
  std::set<const EdgeTraffic*> placed;
  std::function<void(const std::string&, int)> visit = [&](const std::string& frame, int depth) {
    const auto found = children_of.find(frame);
    if (found == children_of.end()) return;
    std::vector<const EdgeTraffic*> below = found->second;
    std::stable_sort(below.begin(), below.end(), [](const EdgeTraffic* a, const EdgeTraffic* b) {
      return a->child < b->child;
    });
    for (const EdgeTraffic* edge : below) {
      if (!placed.insert(edge).second) continue;
      order.emplace_back(edge, depth);
      if (main_edge_of[edge->child] == edge) visit(edge->child, depth + 1);
    }
  };
  for (const auto& [parent, edges_below] : children_of) {
    if (!main_edge_of.count(parent)) visit(parent, 0);
  }
  for (const EdgeTraffic& edge : edges) {
    if (placed.insert(&edge).second) order.emplace_back(&edge, 0);
  }
  return order;
}

void writeChain(std::ostream& out, const ChainReport& chain) {
  out << "Chain from '" << chain.frame_a << "' to '" << chain.frame_b << "': ";
  if (!chain.problem.empty()) {
    out << "none yet: " << chain.problem << "\n\n";
    return;
  }
  out << joined(chain.frames, " -> ") << '\n';
  if (chain.samples == 0) {
    out << "  net delay: none measured (every edge static, or no dynamic update heard)\n\n";
    return;
  }
  out << "  net delay: average " << milliseconds(chain.average_delay_s) << " ms, max "
      << milliseconds(chain.max_delay_s) << " ms over " << chain.samples << " updates\n\n";
}

void writeFrames(std::ostream& out, const TrafficSummary& summary, const ChainReport* chain) {
  std::set<std::string> on_chain;
  if (chain) on_chain.insert(chain->frames.begin(), chain->frames.end());
  TextTable table({"frame", "parent", "authority", "rate Hz", "delay avg ms", "max ms", "buffered"},
                  {false, false, false, true, true, true, true});
  for (const auto& [edge, depth] : treeOrder(summary.edges)) {
    const bool chained = on_chain.count(edge->child) && on_chain.count(edge->parent);
    table.addRow({std::string(static_cast<std::size_t>(2 * depth), ' ') + edge->child +
                      (chained ? " *" : ""),
                  edge->parent, joined(edge->authorities, ", "), rate(edge->rate_hz),
                  edge->is_static ? "static" : milliseconds(edge->average_delay_s),
                  edge->is_static ? "-" : milliseconds(edge->max_delay_s),
                  std::to_string(edge->buffered)});
  }
  out << "Frames" << (chain && !on_chain.empty() ? " (* on the chain)" : "") << ":\n"
      << table.render() << '\n';
}

void writeAuthorities(std::ostream& out, const TrafficSummary& summary) {
  TextTable table({"authority", "messages", "rate Hz", "delay avg ms", "max ms", "frames"},
                  {false, true, true, true, true, false});
  for (const AuthorityTraffic& authority : summary.authorities) {
    const bool timed = authority.dynamic_samples > 0;
    table.addRow({authority.authority, std::to_string(authority.messages), rate(authority.rate_hz),
                  timed ? milliseconds(authority.average_delay_s) : "static",
                  timed ? milliseconds(authority.max_delay_s) : "-",
                  joined(authority.frames, ", ", 6)});
  }
  out << "Authorities:\n" << table.render() << '\n';
}

// Only senders whose numbered batches did not all arrive once and in order.
void writeSequenceTrouble(std::ostream& out, const TrafficSummary& summary) {
  TextTable table({"authority", "lost", "reordered", "duplicated", "restarts"},
                  {false, true, true, true, true});
  bool any = false;
  for (const AuthorityTraffic& authority : summary.authorities) {
    const SequenceCounts& counts = authority.sequence;
    if (!counts.lost && !counts.reordered && !counts.duplicated && !counts.restarts) continue;
    any = true;
    table.addRow({authority.authority, std::to_string(counts.lost),
                  std::to_string(counts.reordered), std::to_string(counts.duplicated),
                  std::to_string(counts.restarts)});
  }
  if (!any) return;
  out << "Batches lost, reordered or duplicated on the way (by their numbers, since start):\n"
      << table.render() << '\n';
}

}  // namespace

std::string formatMonitorReport(const TrafficSummary& received, const std::string& source,
                                const ChainReport* received_chain) {
  const TrafficSummary summary = shownSafely(received);
  const std::optional<ChainReport> safe_chain =
      received_chain ? std::optional<ChainReport>(shownSafely(*received_chain)) : std::nullopt;
  const ChainReport* chain = safe_chain ? &*safe_chain : nullptr;
  std::ostringstream out;
  const double seconds = toSeconds(summary.window_end - summary.window_start);
  out << "Heard " << summary.edges.size() << " edge" << (summary.edges.size() == 1 ? "" : "s")
      << " from " << summary.authorities.size() << " authorit"
      << (summary.authorities.size() == 1 ? "y" : "ies") << " on " << printable(source)
      << " in the " << fixedDecimals(seconds, 3) << " s up to " << toString(summary.window_end)
      << ".\n\n";
  if (chain) writeChain(out, *chain);
  if (summary.edges.empty()) {
    out << "No transforms heard in this window.\n";
  } else {
    writeFrames(out, summary, chain);
    writeAuthorities(out, summary);
    writeSequenceTrouble(out, summary);
  }
  if (!summary.conflicts.empty()) {
    out << "Conflicts (a frame sent by more than one authority):\n";
    for (const FrameConflict& conflict : summary.conflicts) {
      out << "  '" << conflict.child << "' from " << joined(conflict.senders, "; ") << '\n';
    }
    out << '\n';
  }
  if (!summary.problems.empty()) {
    out << "Problems since start (" << summary.malformed << " malformed messages, "
        << summary.invalid_transforms << " invalid transforms, " << summary.refused
        << " refused over limits):\n";
    for (const std::string& problem : summary.problems) out << "  " << problem << '\n';
  }
  return out.str();
}

}  // namespace lcmtf::nodes
