#include "lcmtf_viewer/scene_snapshot.hpp"

#include <algorithm>
#include <set>

#include "lcmtf/exceptions.hpp"

namespace lcmtf::viewer {

FrameForest readForest(const BufferCore& buffer, TimePoint now) {
  FrameForest forest;
  forest.now = now;
  forest.edges = buffer.describeEdges();
  std::set<std::string> parents;
  bool any_dynamic = false;
  for (const EdgeDescription& edge : forest.edges) {
    forest.parent_of[edge.child] = edge.parent;
    parents.insert(edge.parent);
    if (edge.is_static) continue;
    forest.oldest = any_dynamic ? std::min(forest.oldest, edge.oldest) : edge.oldest;
    forest.newest = any_dynamic ? std::max(forest.newest, edge.newest) : edge.newest;
    any_dynamic = true;
  }
  for (const std::string& parent : parents) {
    if (!forest.parent_of.count(parent)) forest.roots.push_back(parent);
  }
  for (const std::string& root : forest.roots) forest.trees[root].push_back(root);
  for (const auto& [child, parent] : forest.parent_of) {
    forest.trees[rootOf(forest, child)].push_back(child);
  }
  for (auto& [root, frames] : forest.trees) std::sort(frames.begin() + 1, frames.end());
  return forest;
}

std::string rootOf(const FrameForest& forest, const std::string& frame) {
  std::string root = frame;
  // A loop cannot be stored, but the walk is bounded all the same.
  for (std::size_t steps = 0; steps <= forest.parent_of.size(); ++steps) {
    const auto parent = forest.parent_of.find(root);
    if (parent == forest.parent_of.end()) break;
    root = parent->second;
  }
  return root;
}

namespace {

FramePose toPose(const Transform& transform) {
  const Eigen::Vector3d& t = transform.translation;
  const Eigen::Quaterniond& q = transform.rotation;
  return {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()};
}

}  // namespace

bool knowsFrame(const FrameForest& forest, const std::string& frame) {
  return forest.parent_of.count(frame) ||
         std::binary_search(forest.roots.begin(), forest.roots.end(), frame);
}

std::string automaticFixedFrame(const FrameForest& forest, const std::string& preferred) {
  if (!preferred.empty() && knowsFrame(forest, preferred)) return preferred;
  std::string largest;
  std::size_t most = 0;
  for (const auto& [root, frames] : forest.trees) {
    if (frames.size() > most) {
      most = frames.size();
      largest = root;
    }
  }
  return largest;
}

SceneSnapshot takeSnapshot(const BufferCore& buffer, const FrameForest& forest,
                           const std::string& fixed_frame, std::optional<TimePoint> paused_at,
                           Duration stale_after) {
  SceneSnapshot scene;
  scene.fixed_frame = fixed_frame;
  scene.live = !paused_at.has_value();
  scene.time = paused_at.value_or(forest.newest);
  const std::string fixed_root = rootOf(forest, fixed_frame);
  const bool fixed_known = !fixed_frame.empty() && knowsFrame(forest, fixed_frame);
  for (const auto& [root, frames] : forest.trees) {
    if (!fixed_known || root != fixed_root) {
      scene.unconnected.push_back(UnconnectedTree{root, frames});
      continue;
    }
    const TimePoint time = paused_at.value_or(kLatestTime);
    for (const std::string& frame : frames) {
      if (frame == fixed_frame) {
        scene.poses[frame] = {0, 0, 0, 0, 0, 0, 1};
        continue;
      }
      try {
        scene.poses[frame] = toPose(buffer.lookupTransform(fixed_frame, frame, time).transform);
      } catch (const TransformException&) {
        // Not drawable at this time: the page is told it is gone.
      }
    }
  }
  for (const EdgeDescription& edge : forest.edges) {
    if (!edge.is_static && forest.now - edge.newest > stale_after) {
      scene.stale.push_back(edge.child);
    }
  }
  std::sort(scene.stale.begin(), scene.stale.end());
  return scene;
}

}  // namespace lcmtf::viewer
