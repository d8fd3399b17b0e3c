#pragma once

// The tree shapes the buffer benchmarks measure. A margin measured on one shape says little of
// another: short paths weigh each lookup's fixed costs, long ones the cost per edge, and a
// large forest the memory's latency.

#include <random>
#include <string>
#include <vector>

#include "tree_workload.hpp"

namespace bench {

namespace detail {

// A trunk, one limb reaching depth 27, more limbs off the trunk and upper limbs, and short
// sensor and finger branches, until there are `frames` frames.
inline void buildPr2Tree(Workload& w, std::mt19937_64& rng, std::size_t frames) {
  static const char* const kLimbs[] = {"torso", "head", "l_arm", "r_arm", "laser", "camera"};
  static const char* const kParts[] = {"shoulder_pan", "upper_arm_roll", "elbow_flex",
                                       "forearm_roll", "wrist_flex",     "gripper_palm",
                                       "finger_tip",   "optical",        "mount"};
  auto add = [&](std::size_t parent, const std::string& limb) {
    const std::size_t id = w.frameCount();
    return addFrame(w, parent, limb + "_" + kParts[id % 9] + "_" + std::to_string(id) + "_link");
  };
  addFrame(w, 0, "map");
  addFrame(w, 0, "odom_combined");
  addFrame(w, 1, "base_footprint");
  addFrame(w, 2, "base_link");
  std::size_t frame = addFrame(w, 3, "torso_lift_link");
  while (w.depth[frame] < 27) frame = add(frame, "r_arm");
  std::size_t limb = 0;
  while (w.frameCount() < frames) {
    const bool branch = limb++ % 3 != 0;
    std::size_t at = std::uniform_int_distribution<std::size_t>(2, 4)(rng);
    if (branch) {
      do {
        at = std::uniform_int_distribution<std::size_t>(5, w.frameCount() - 1)(rng);
      } while (w.depth[at] > 20);
    }
    const std::size_t length = branch ? std::uniform_int_distribution<std::size_t>(1, 4)(rng)
                                      : std::uniform_int_distribution<std::size_t>(12, 18)(rng);
    for (std::size_t i = 0; i < length && w.frameCount() < frames; ++i) {
      at = add(at, kLimbs[limb % 6]);
    }
  }
}

// A chain of `chain_edges` edges from the root, then frames hung one by one from frames chosen
// at random among those already there, so that most paths run a long way along the chain.
inline void buildDeepChain(Workload& w, std::mt19937_64& rng, std::size_t chain_edges,
                           std::size_t frames) {
  std::size_t frame = addFrame(w, 0, "world");
  for (std::size_t i = 1; i <= chain_edges; ++i) {
    frame = addFrame(w, frame, "chain_link_" + std::to_string(i));
  }
  while (w.frameCount() < frames) {
    const std::size_t at = std::uniform_int_distribution<std::size_t>(1, w.frameCount() - 1)(rng);
    addFrame(w, at, "branch_" + std::to_string(w.frameCount()) + "_link");
  }
}

// map -> odom -> base_link, a few dozen mounts under base_link, and every other frame (markers,
// tracked objects, sensor frames) one or two steps below base_link or a mount.
inline void buildWideTree(Workload& w, std::mt19937_64& rng, std::size_t frames) {
  addFrame(w, 0, "map");
  addFrame(w, 0, "odom");
  addFrame(w, 1, "base_link");
  constexpr std::size_t kMounts = 40;
  for (std::size_t i = 0; i < kMounts; ++i) addFrame(w, 2, "mount_" + std::to_string(i));
  while (w.frameCount() < frames) {
    const std::size_t at = std::uniform_int_distribution<std::size_t>(2, w.frameCount() - 1)(rng);
    if (w.depth[at] > 3) continue;
    addFrame(w, at, "object_" + std::to_string(w.frameCount()));
  }
}

// `trees` trees, each one a 4-ary tree of `frames_per_tree` frames.
inline void buildForest(Workload& w, std::size_t trees, std::size_t frames_per_tree) {
  for (std::size_t t = 0; t < trees; ++t) {
    const std::size_t base = w.frameCount();
    const std::string prefix = "robot_" + std::to_string(t) + "/";
    addFrame(w, base, prefix + "map");
    for (std::size_t j = 1; j < frames_per_tree; ++j) {
      addFrame(w, base + (j - 1) / 4, prefix + "frame_" + std::to_string(j));
    }
  }
}

// A workload named `shape`, its tree built by `build(w, rng)`, `dynamic_fraction` of its edges
// moving with `samples` samples each.
template <class BuildTree>
Workload makeWorkload(const char* shape, std::size_t samples, std::uint64_t seed,
                      double dynamic_fraction, std::int64_t stamp_jitter, BuildTree build) {
  Workload w;
  w.shape = shape;
  w.samples = samples;
  w.stamp_jitter = stamp_jitter;
  std::mt19937_64 rng(seed);
  build(w, rng);
  buildMotion(w, rng, dynamic_fraction);
  buildQueries(w, rng);
  return w;
}

}  // namespace detail

/// The robot of the first measurements: 100 frames, a third of the edges dynamic with 10 s at
/// 100 Hz, one limb 27 deep.
inline Workload makePr2Workload(std::int64_t stamp_jitter = 0) {
  return detail::makeWorkload("pr2", 1000, 20240601, 1.0 / 3.0, stamp_jitter,
                              [](Workload& w, auto& rng) { detail::buildPr2Tree(w, rng, 100); });
}

/// 100 frames around a chain 30 edges deep, a third of the edges dynamic with 10 s at 100 Hz.
inline Workload makeDeepChainWorkload(std::int64_t stamp_jitter = 0) {
  return detail::makeWorkload(
      "deep_chain", 1000, 27, 1.0 / 3.0, stamp_jitter,
      [](Workload& w, auto& rng) { detail::buildDeepChain(w, rng, 30, 100); });
}

/// 1,000 frames at most five edges below the root, a third dynamic with 10 s at 100 Hz.
inline Workload makeWideWorkload(std::int64_t stamp_jitter = 0) {
  return detail::makeWorkload("wide", 1000, 1000, 1.0 / 3.0, stamp_jitter,
                              [](Workload& w, auto& rng) { detail::buildWideTree(w, rng, 1000); });
}

/// 100,000 frames in ten 4-ary trees, half the edges dynamic with 0.2 s at 100 Hz.
inline Workload makeForestWorkload(std::int64_t stamp_jitter = 0) {
  return detail::makeWorkload("forest", 20, 100000, 0.5, stamp_jitter,
                              [](Workload& w, auto&) { detail::buildForest(w, 10, 10'000); });
}

}  // namespace bench
