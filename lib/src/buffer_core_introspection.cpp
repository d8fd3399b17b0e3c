// The YAML and Graphviz views of the frame tree.
#include <cstdio>
#include <shared_mutex>
#include <sstream>

#include "buffer_core_impl.hpp"
#include "lcmtf/printable.hpp"

namespace lcmtf {

namespace {

struct EdgeSummary {
  bool is_static = false;
  double rate_hz = 0.0;
  std::int64_t oldest = 0;
  std::int64_t newest = 0;
  std::size_t samples = 0;
};

EdgeSummary summarize(const detail::TimeCache& cache) {
  EdgeSummary summary;
  summary.is_static = cache.isStatic();
  summary.samples = cache.size();
  if (summary.is_static || cache.empty()) return summary;
  summary.oldest = cache.oldestStamp();
  summary.newest = cache.newestStamp();
  if (summary.samples > 1 && summary.newest > summary.oldest) {
    summary.rate_hz = static_cast<double>(summary.samples - 1) /
                      toSeconds(Duration(summary.newest - summary.oldest));
  }
  return summary;
}

std::string yamlQuoted(std::string_view text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') quoted += '\'';
    quoted += c;
  }
  return quoted + "'";
}

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace

std::vector<EdgeDescription> BufferCore::describeEdges() const {
  std::shared_lock<detail::ReadMostlyLock> lock(impl_->lock_);
  std::vector<EdgeDescription> edges;
  for (std::size_t id = 1; id < impl_->frames_.size(); ++id) {
    const FrameRecord& frame = impl_->frames_[id];
    if (frame.cache.empty()) continue;
    const EdgeSummary summary = summarize(frame.cache);
    EdgeDescription& edge = edges.emplace_back();
    edge.child = frame.name;
    edge.parent = impl_->nameOf(frame.cache.newestParent());
    if (frame.authority) edge.authority = impl_->authorities_.name(frame.authority);
    edge.is_static = summary.is_static;
    edge.rate_hz = summary.rate_hz;
    edge.samples = summary.samples;
    edge.oldest = fromUtime(summary.oldest);
    edge.newest = fromUtime(summary.newest);
  }
  return edges;
}

std::string BufferCore::allFramesAsYaml() const {
  std::shared_lock<detail::ReadMostlyLock> lock(impl_->lock_);
  std::ostringstream yaml;
  for (std::size_t id = 1; id < impl_->frames_.size(); ++id) {
    const FrameRecord& frame = impl_->frames_[id];
    if (frame.cache.empty()) continue;
    const EdgeSummary edge = summarize(frame.cache);
    yaml << yamlQuoted(frame.name) << ":\n"
         << "  parent: " << yamlQuoted(impl_->nameOf(frame.cache.newestParent())) << '\n'
         << "  authority: "
         << yamlQuoted(frame.authority ? impl_->authorities_.name(frame.authority) : "") << '\n'
         << "  static: " << (edge.is_static ? "true" : "false") << '\n'
         << "  rate: " << fixed(edge.rate_hz, 3) << '\n'
         << "  samples: " << edge.samples << '\n'
         << "  most_recent_transform: " << toString(fromUtime(edge.newest)) << '\n'
         << "  oldest_transform: " << toString(fromUtime(edge.oldest)) << '\n'
         << "  buffer_length: " << fixed(toSeconds(Duration(edge.newest - edge.oldest)), 6) << '\n'
         << "  authority_conflicts: " << frame.authority_conflicts << '\n';
  }
  return yaml.str();
}

std::string BufferCore::allFramesAsDot() const {
  std::shared_lock<detail::ReadMostlyLock> lock(impl_->lock_);
  std::ostringstream dot;
  dot << "digraph lcmtf {\n  rankdir=TB;\n  node [shape=box];\n";
  for (std::size_t id = 1; id < impl_->frames_.size(); ++id) {
    const FrameRecord& frame = impl_->frames_[id];
    dot << "  " << dotQuoted(frame.name) << ";\n";
  }
  for (std::size_t id = 1; id < impl_->frames_.size(); ++id) {
    const FrameRecord& frame = impl_->frames_[id];
    if (frame.cache.empty()) continue;
    const EdgeSummary edge = summarize(frame.cache);
    const std::string authority =
        frame.authority ? impl_->authorities_.name(frame.authority) : std::string();
    std::string label = "Broadcaster: " + authority + "\n";
    if (edge.is_static) {
      label += "static";
    } else {
      label += "Average rate: " + fixed(edge.rate_hz, 3) +
               " Hz\nMost recent transform: " + toString(fromUtime(edge.newest)) +
               "\nBuffer length: " + fixed(toSeconds(Duration(edge.newest - edge.oldest)), 3) +
               " s";
    }
    dot << "  " << dotQuoted(impl_->nameOf(frame.cache.newestParent())) << " -> "
        << dotQuoted(frame.name) << " [label=" << dotQuoted(label)
        << (edge.is_static ? ", style=dashed" : "") << "];\n";
  }
  dot << "}\n";
  return dot.str();
}

}  // namespace lcmtf
