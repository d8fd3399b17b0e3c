#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "frame_record.hpp"
#include "large_arrays.hpp"

namespace lcmtf {

/// One step up the tree as lookups take it: a chain of static edges to the highest frame it
/// reaches, a single static edge (on a loop of static edges), or one dynamic edge, anchored
/// to the static chain above its parent when there is one.
struct RootStep {
  const detail::TimeCache* cache = nullptr;  // a dynamic edge's history; null when static
  const Transform* fixed = nullptr;          // a static step's value
  FrameId child = kNoFrame;
  FrameId parent = kNoFrame;  // the edge's parent (for a chain, where it ends)
  FrameId next = kNoFrame;    // where the step ends; kNoFrame above a root
  // A dynamic edge's anchor: the static chain above its parent, which the step crosses too;
  // null when there is none.
  const Transform* anchor = nullptr;
  bool anchored() const { return anchor != nullptr; }
};

/// The step up from `frame`, as of each edge's newest sample.
RootStep stepFrom(const FrameTable& frames, FrameId frame);

/// Every frame's steps up to its root in the tree as of the newest samples, so that a lookup
/// finds its path by comparing two arrays instead of climbing the tree. Rebuilt whenever an
/// edge appears, changes parent or changes between static and dynamic.
class RootPaths {
 public:
  /// Longer paths are not kept: frames deeper than this are looked up by the walk.
  static constexpr std::uint32_t kLongestPath = 64;

  struct Path {
    const RootStep* steps = nullptr;  // from the frame up; steps[size - 1] ends at `root`
    std::uint32_t size = 0;
    FrameId root = kNoFrame;
  };

  void rebuild(const FrameTable& frames);
  /// Adds the paths of the frames added since the last rebuild or extension, when no frame
  /// known then has changed its edge and the paths were built for this table: in time
  /// proportional to the new frames' paths rather than to every frame's.
  void extend(const FrameTable& frames);
  /// Whether extend() can bring the paths up to date with `frames`.
  bool canExtendTo(const FrameTable& frames) const { return &frames == built_for_; }
  /// Makes find() fail for every frame until the next rebuild: the paths no longer match the
  /// tree.
  void invalidate() { built_for_ = nullptr; }
  /// How many frames have paths (or are known to have none).
  std::size_t frameCount() const { return entries_.size(); }
  /// The path up from `frame` of `frames`, or false when there is none to trust: a frame added
  /// since the last rebuild, one on or below a loop or deeper than kLongestPath steps, or
  /// another table than the paths were built for (the steps point into its records).
  bool find(const FrameTable& frames, FrameId frame, Path& path) const {
    if (&frames != built_for_ || frame >= entries_.size() || !entries_[frame].usable) {
      return false;
    }
    const Entry& entry = entries_[frame];
    path = Path{entry.steps, entry.size, entry.root};
    return true;
  }

 private:
  struct Entry {
    const RootStep* steps = nullptr;
    std::uint32_t size = 0;
    FrameId root = kNoFrame;
    bool usable = false;
  };

  /// Room for `count` consecutive steps that stays where it is until the next rebuild.
  RootStep* allocateSteps(std::size_t count);

  /// Works out the paths of frames `first` on; the frames before have theirs.
  void settleFrom(const FrameTable& frames, FrameId first);

  // The steps of every path, in chunks that never move, each twice the one before.
  std::vector<std::vector<RootStep, detail::LargeArrayAllocator<RootStep>>> step_chunks_;
  std::size_t last_chunk_size_ = 0;
  std::size_t last_chunk_used_ = 0;
  std::vector<Entry, detail::LargeArrayAllocator<Entry>> entries_;
  const FrameTable* built_for_ = nullptr;
};

}  // namespace lcmtf
