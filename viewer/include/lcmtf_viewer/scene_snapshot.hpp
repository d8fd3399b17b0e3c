#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/edge_description.hpp"
#include "lcmtf/time.hpp"

namespace lcmtf::viewer {

/// A frame's pose in the fixed frame: x, y, z, qx, qy, qz, qw.
using FramePose = std::array<double, 7>;

/// A tree of frames that has no path to the fixed frame.
struct UnconnectedTree {
  std::string root;
  std::vector<std::string> frames;  ///< the root first, then the others sorted
  friend bool operator==(const UnconnectedTree& a, const UnconnectedTree& b) {
    return a.root == b.root && a.frames == b.frames;
  }
};

/// The frames' tree as the buffer holds it at one moment, shared by every page's scene.
struct FrameForest {
  std::vector<EdgeDescription> edges;
  std::map<std::string, std::string> parent_of;  ///< child -> parent
  std::vector<std::string> roots;                ///< frames with no parent, sorted
  /// Each tree's frames by its root: the root first, then the others sorted.
  std::map<std::string, std::vector<std::string>> trees;
  TimePoint oldest;  ///< over dynamic edges; zero when none
  TimePoint newest;
  TimePoint now;  ///< when it was read
};

/// Reads the buffer's edges and works out the trees they make.
FrameForest readForest(const BufferCore& buffer, TimePoint now);

/// The root of the tree `frame` belongs to (itself when it has no parent).
std::string rootOf(const FrameForest& forest, const std::string& frame);
/// Whether `frame` is in one of the trees.
bool knowsFrame(const FrameForest& forest, const std::string& frame);

/// The fixed frame to draw in when the page has not chosen one: `preferred` when the buffer
/// knows it, else the root of the largest tree; "" when the buffer is empty.
std::string automaticFixedFrame(const FrameForest& forest, const std::string& preferred);

/// What one page draws: every frame it can in the fixed frame, at a time.
struct SceneSnapshot {
  std::string fixed_frame;
  bool live = true;
  TimePoint time;                          ///< the stamp drawn
  std::map<std::string, FramePose> poses;  ///< frames that could be looked up
  std::vector<UnconnectedTree> unconnected;
  std::vector<std::string> stale;  ///< dynamic edges' children with no new stamp lately
};

/// The scene in `fixed_frame`: live (each frame at its chain's latest common time) or at
/// `paused_at`. Frames whose lookup fails there are left out.
SceneSnapshot takeSnapshot(const BufferCore& buffer, const FrameForest& forest,
                           const std::string& fixed_frame, std::optional<TimePoint> paused_at,
                           Duration stale_after);

}  // namespace lcmtf::viewer
