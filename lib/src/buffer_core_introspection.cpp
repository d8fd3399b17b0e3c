// The YAML and Graphviz views of the frame tree.
#include <cstdio>
#include <sstream>

#include "buffer_core_impl.hpp"
#include "lcmtf/printable.hpp"

namespace lcmtf {

namespace {

// Every edge held, in the order its child appeared; the caller holds the buffer's lock.
std::vector<EdgeDescription> describeEdgesOf(const FrameTable& frames,
                                             const detail::AuthorityTable& authorities) {
  std::vector<EdgeDescription> edges;
  for (std::size_t id = 1; id < frames.size(); ++id) {
    const FrameRecord& frame = frames[id];
    const detail::TimeCache& cache = frame.cache;
    if (cache.empty()) continue;
    EdgeDescription& edge = edges.emplace_back();
    edge.child = frame.name;
    edge.parent = frames[cache.newestParent()].name;
    if (frame.authority) edge.authority = authorities.name(frame.authority);
    edge.is_static = cache.isStatic();
    edge.samples = cache.size();
    edge.authority_conflicts = frame.authority_conflicts;
    if (edge.is_static) continue;
    edge.oldest = fromUtime(cache.oldestStamp());
    edge.newest = fromUtime(cache.newestStamp());
    if (edge.samples > 1 && edge.newest > edge.oldest) {
      edge.rate_hz = static_cast<double>(edge.samples - 1) / toSeconds(edge.newest - edge.oldest);
    }
  }
  return edges;
}

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace

std::vector<EdgeDescription> BufferCore::describeEdges() const {
  SharedLock lock(impl_->lock_);
  return describeEdgesOf(impl_->frames_, impl_->authorities_);
}

std::string BufferCore::allFramesAsYaml() const {
  SharedLock lock(impl_->lock_);
  std::ostringstream yaml;
  for (const EdgeDescription& edge : describeEdgesOf(impl_->frames_, impl_->authorities_)) {
    yaml << yamlQuoted(edge.child) << ":\n"
         << "  parent: " << yamlQuoted(edge.parent) << '\n'
         << "  authority: " << yamlQuoted(edge.authority) << '\n'
         << "  static: " << (edge.is_static ? "true" : "false") << '\n'
         << "  rate: " << fixed(edge.rate_hz, 3) << '\n'
         << "  samples: " << edge.samples << '\n'
         << "  most_recent_transform: " << toString(edge.newest) << '\n'
         << "  oldest_transform: " << toString(edge.oldest) << '\n'
         << "  buffer_length: " << fixed(toSeconds(edge.newest - edge.oldest), 6) << '\n'
         << "  authority_conflicts: " << edge.authority_conflicts << '\n';
  }
  return yaml.str();
}

std::string BufferCore::allFramesAsDot() const {
  SharedLock lock(impl_->lock_);
  std::ostringstream dot;
  dot << "digraph lcmtf {\n  rankdir=TB;\n  node [shape=box];\n";
  for (std::size_t id = 1; id < impl_->frames_.size(); ++id) {
    const FrameRecord& frame = impl_->frames_[id];
    dot << "  " << dotQuoted(frame.name) << ";\n";
  }
  for (const EdgeDescription& edge : describeEdgesOf(impl_->frames_, impl_->authorities_)) {
    std::string label = "Broadcaster: " + edge.authority + "\n";
    if (edge.is_static) {
      label += "static";
    } else {
      label += "Average rate: " + fixed(edge.rate_hz, 3) +
               " Hz\nMost recent transform: " + toString(edge.newest) +
               "\nBuffer length: " + fixed(toSeconds(edge.newest - edge.oldest), 3) + " s";
    }
    dot << "  " << dotQuoted(edge.parent) << " -> " << dotQuoted(edge.child)
        << " [label=" << dotQuoted(label) << (edge.is_static ? ", style=dashed" : "") << "];\n";
  }
  dot << "}\n";
  return dot.str();
}

}  // namespace lcmtf
