#pragma once

// A PR2-scale frame tree with smooth motion, generated from a fixed seed so that every library
// under test sees exactly the same frames, samples and queries.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace bench {

struct Pose {
  double x = 0, y = 0, z = 0;
  double qx = 0, qy = 0, qz = 0, qw = 1;
};

struct Edge {
  std::size_t parent = 0;
  std::size_t child = 0;
  bool dynamic = false;
  std::int64_t first_stamp = 0;  // utime of sample 0; dynamic edges only
  std::vector<Pose> samples;     // one for a static edge, the history for a dynamic one
};

struct Query {
  std::size_t target = 0;
  std::size_t source = 0;
  std::int64_t time = 0;
  std::int64_t other_time = 0;
};

struct Workload {
  static constexpr std::size_t kFrames = 100;
  static constexpr std::size_t kSamples = 1000;
  static constexpr std::int64_t kPeriod = 10'000;  // 100 Hz in microseconds
  static constexpr std::int64_t kEpoch = 1'700'000'000'000'000;
  static constexpr std::size_t kQueries = 4096;

  std::vector<std::string> names;
  std::vector<std::size_t> parent;  // parent[0] is the root's own index
  std::vector<std::size_t> depth;
  std::vector<Edge> edges;  // edges[i] has child frame i + 1
  std::size_t deepest = 0;
  std::int64_t oldest_common = 0;  // every dynamic edge has data in [oldest, newest]
  std::int64_t newest_common = 0;
  std::vector<Query> random_pairs;
  std::vector<Query> deepest_chain;

  std::int64_t stamp(const Edge& edge, std::size_t k) const {
    return edge.first_stamp + static_cast<std::int64_t>(k) * kPeriod;
  }
  std::size_t dynamicEdgeCount() const {
    return static_cast<std::size_t>(
        std::count_if(edges.begin(), edges.end(), [](const Edge& e) { return e.dynamic; }));
  }
  std::size_t storedSamples() const {
    std::size_t n = 0;
    for (const Edge& e : edges) n += e.samples.size();
    return n;
  }
  // Edges between two frames and how many of them are dynamic.
  std::pair<std::size_t, std::size_t> pathLength(std::size_t a, std::size_t b) const {
    std::size_t total = 0;
    std::size_t dynamic = 0;
    while (a != b) {
      std::size_t& deeper = depth[a] >= depth[b] ? a : b;
      ++total;
      dynamic += edges[deeper - 1].dynamic ? 1 : 0;
      deeper = parent[deeper];
    }
    return {total, dynamic};
  }
};

namespace detail {

inline Pose poseOf(double x, double y, double z, double ax, double ay, double az, double angle) {
  const double norm = std::sqrt(ax * ax + ay * ay + az * az);
  const double s = std::sin(angle / 2) / norm;
  return Pose{x, y, z, ax * s, ay * s, az * s, std::cos(angle / 2)};
}

// `motion` applied on top of `base`: rotations composed, translations added.
inline Pose perturb(const Pose& a, const Pose& b) {
  Pose r = b;
  r.qw = a.qw * b.qw - a.qx * b.qx - a.qy * b.qy - a.qz * b.qz;
  r.qx = a.qw * b.qx + a.qx * b.qw + a.qy * b.qz - a.qz * b.qy;
  r.qy = a.qw * b.qy - a.qx * b.qz + a.qy * b.qw + a.qz * b.qx;
  r.qz = a.qw * b.qz + a.qx * b.qy - a.qy * b.qx + a.qz * b.qw;
  const double n = std::sqrt(r.qw * r.qw + r.qx * r.qx + r.qy * r.qy + r.qz * r.qz);
  r.qw /= n;
  r.qx /= n;
  r.qy /= n;
  r.qz /= n;
  r.x = a.x + b.x;
  r.y = a.y + b.y;
  r.z = a.z + b.z;
  return r;
}

// A trunk, one limb reaching depth 27, more limbs off the trunk and upper limbs, and short
// sensor and finger branches, until there are kFrames frames.
inline void buildTree(Workload& w, std::mt19937_64& rng) {
  static const char* const kLimbs[] = {"torso", "head", "l_arm", "r_arm", "laser", "camera"};
  static const char* const kParts[] = {"shoulder_pan", "upper_arm_roll", "elbow_flex",
                                       "forearm_roll", "wrist_flex",     "gripper_palm",
                                       "finger_tip",   "optical",        "mount"};
  auto add = [&](std::size_t parent, const std::string& limb) {
    const std::size_t id = w.names.size();
    w.names.push_back(limb + "_" + kParts[id % 9] + "_" + std::to_string(id) + "_link");
    w.parent.push_back(parent);
    w.depth.push_back(w.depth[parent] + 1);
    return id;
  };
  w.names = {"map", "odom_combined", "base_footprint", "base_link", "torso_lift_link"};
  w.parent = {0, 0, 1, 2, 3};
  w.depth = {0, 1, 2, 3, 4};
  std::size_t frame = 4;
  while (w.depth[frame] < 27) frame = add(frame, "r_arm");
  w.deepest = frame;
  std::size_t limb = 0;
  while (w.names.size() < Workload::kFrames) {
    const bool branch = limb++ % 3 != 0;
    std::size_t at = std::uniform_int_distribution<std::size_t>(2, 4)(rng);
    if (branch) {
      do {
        at = std::uniform_int_distribution<std::size_t>(5, w.names.size() - 1)(rng);
      } while (w.depth[at] > 20);
    }
    const std::size_t length = branch ? std::uniform_int_distribution<std::size_t>(1, 4)(rng)
                                      : std::uniform_int_distribution<std::size_t>(12, 18)(rng);
    for (std::size_t i = 0; i < length && w.names.size() < Workload::kFrames; ++i) {
      at = add(at, kLimbs[limb % 6]);
    }
  }
}

inline void buildMotion(Workload& w, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<bool> dynamic(Workload::kFrames - 1, false);
  std::fill(dynamic.begin(), dynamic.begin() + (Workload::kFrames - 1) / 3, true);
  std::shuffle(dynamic.begin(), dynamic.end(), rng);
  constexpr double kTwoPi = 6.283185307179586;
  for (std::size_t child = 1; child < Workload::kFrames; ++child) {
    Edge edge;
    edge.parent = w.parent[child];
    edge.child = child;
    edge.dynamic = dynamic[child - 1];
    const Pose base = poseOf(0.3 * unit(rng), 0.3 * unit(rng), 0.3 * unit(rng), unit(rng),
                             unit(rng), unit(rng) + 2.5, 3.0 * unit(rng));
    if (!edge.dynamic) {
      edge.samples.push_back(base);
      w.edges.push_back(std::move(edge));
      continue;
    }
    const double frequency = 0.1 + 0.45 * (1.0 + unit(rng));
    const double phase = kTwoPi * unit(rng);
    const double amplitude = 0.2 * unit(rng);
    const double swing = 1.2 * unit(rng);
    const double ax = unit(rng), ay = unit(rng), az = unit(rng) + 2.5;
    edge.first_stamp = Workload::kEpoch +
                       std::uniform_int_distribution<std::int64_t>(0, Workload::kPeriod - 1)(rng);
    for (std::size_t k = 0; k < Workload::kSamples; ++k) {
      const double t = static_cast<double>(k * Workload::kPeriod) * 1e-6;
      const double wave = std::sin(kTwoPi * frequency * t + phase);
      const Pose motion =
          poseOf(amplitude * wave, 0.5 * amplitude * wave, 0.0, ax, ay, az, swing * wave);
      edge.samples.push_back(perturb(base, motion));
    }
    w.edges.push_back(std::move(edge));
  }
}

inline void buildQueries(Workload& w, std::mt19937_64& rng) {
  w.oldest_common = 0;
  w.newest_common = INT64_MAX;
  for (const Edge& e : w.edges) {
    if (!e.dynamic) continue;
    w.oldest_common = std::max(w.oldest_common, w.stamp(e, 0));
    w.newest_common = std::min(w.newest_common, w.stamp(e, Workload::kSamples - 1));
  }
  std::uniform_int_distribution<std::int64_t> time(w.oldest_common, w.newest_common);
  std::uniform_int_distribution<std::size_t> frame(0, Workload::kFrames - 1);
  for (std::size_t i = 0; i < Workload::kQueries; ++i) {
    Query q;
    q.target = frame(rng);
    do {
      q.source = frame(rng);
    } while (q.source == q.target);
    q.time = time(rng);
    q.other_time = time(rng);
    w.random_pairs.push_back(q);
    const bool up = i % 2 == 0;
    w.deepest_chain.push_back(Query{up ? 0 : w.deepest, up ? w.deepest : 0, q.time, q.other_time});
  }
}

}  // namespace detail

inline std::vector<std::size_t> dynamicEdges(const Workload& w) {
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < w.edges.size(); ++i) {
    if (w.edges[i].dynamic) indices.push_back(i);
  }
  return indices;
}

// Gives `subject` (anything with set(edge, utime, pose, is_static)) every static edge, then
// every dynamic edge's samples in time order, a round of all edges at a time.
template <class Subject>
void fill(Subject& subject, const Workload& w) {
  for (std::size_t i = 0; i < w.edges.size(); ++i) {
    if (!w.edges[i].dynamic) subject.set(i, w.oldest_common, w.edges[i].samples[0], true);
  }
  const std::vector<std::size_t> dynamic = dynamicEdges(w);
  for (std::size_t k = 0; k < Workload::kSamples; ++k) {
    for (std::size_t i : dynamic) subject.set(i, w.stamp(w.edges[i], k), w.edges[i].samples[k]);
  }
}

inline Workload makePr2Workload(std::uint64_t seed = 20240601) {
  Workload w;
  std::mt19937_64 rng(seed);
  detail::buildTree(w, rng);
  detail::buildMotion(w, rng);
  detail::buildQueries(w, rng);
  return w;
}

}  // namespace bench
