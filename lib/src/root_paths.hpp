#pragma once

#include <cstdint>
#include <vector>

#include "frame_record.hpp"

namespace lcmtf {

/// One step up the tree as lookups take it: a chain of static edges to the highest frame it
/// reaches, a single static edge (on a loop of static edges), or one dynamic edge, anchored
/// to the static chain above its parent when there is one (see TimeCache::reanchor).
struct RootStep {
  const detail::TimeCache* cache = nullptr;  // a dynamic edge's history; null when static
  const Transform* fixed = nullptr;          // a static step's value
  FrameId child = kNoFrame;
  FrameId parent = kNoFrame;  // the edge's parent (for a chain, where it ends)
  FrameId next = kNoFrame;    // where the step ends; kNoFrame above a root
  bool anchored = false;
};

/// The step up from `frame`, as of each edge's newest sample.
RootStep stepFrom(const std::vector<FrameRecord>& frames, FrameId frame);

/// Every frame's steps up to its root in the tree as of the newest samples, so that a lookup
/// finds its path by comparing two arrays instead of climbing the tree. Rebuilt whenever an
/// edge appears, changes parent or changes between static and dynamic.
class RootPaths {
 public:
  struct Path {
    const RootStep* steps = nullptr;  // from the frame up; steps[size - 1] ends at `root`
    std::uint32_t size = 0;
    FrameId root = kNoFrame;
  };

  void rebuild(const std::vector<FrameRecord>& frames);
  /// The path up from `frame` of `frames`, or false when there is none to trust: a frame added
  /// since the last rebuild, one on or below a loop, or frames that have moved since (the
  /// steps point into them).
  bool find(const std::vector<FrameRecord>& frames, FrameId frame, Path& path) const {
    if (frames.data() != built_for_ || frame >= entries_.size() || !entries_[frame].usable) {
      return false;
    }
    const Entry& entry = entries_[frame];
    path = Path{steps_.data() + entry.offset, entry.size, entry.root};
    return true;
  }

 private:
  struct Entry {
    std::uint32_t offset = 0;
    std::uint32_t size = 0;
    FrameId root = kNoFrame;
    bool usable = false;
  };

  std::vector<RootStep> steps_;
  std::vector<Entry> entries_;
  const FrameRecord* built_for_ = nullptr;
};

}  // namespace lcmtf
