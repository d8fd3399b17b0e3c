#pragma once

// A frame tree (or forest) with smooth motion, generated from a fixed seed so that every library
// under test sees exactly the same frames, samples and queries. tree_shapes.hpp builds the
// shapes the benchmarks measure.

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
  std::size_t fixed = 0;  // the fixed frame of a time-travel lookup: the root of the pair's tree
};

struct Workload {
  static constexpr std::int64_t kPeriod = 10'000;  // 100 Hz in microseconds
  static constexpr std::int64_t kEpoch = 1'700'000'000'000'000;
  static constexpr std::size_t kQueries = 4096;

  std::string shape;        // a short name, as benchmark names give it
  std::size_t samples = 0;  // the history of each dynamic edge
  std::vector<std::string> names;
  std::vector<std::size_t> parent;  // a root's parent is the root itself
  std::vector<std::size_t> depth;
  std::vector<std::size_t> root;
  std::vector<Edge> edges;  // one per frame that is not a root, in the order frames were made
  std::vector<std::size_t> edge_of_frame;  // the index in `edges` of each non-root frame's edge
  std::size_t deepest = 0;                 // the deepest frame of frame 0's tree
  std::int64_t oldest_common = 0;          // every dynamic edge has data in [oldest, newest]
  std::int64_t newest_common = 0;
  std::vector<Query> random_pairs;   // two frames of one tree, at random times
  std::vector<Query> deepest_chain;  // frame 0 and `deepest`, either way round
  // The most a dynamic edge's stamps are off its period, in microseconds, as those of a
  // publisher that stamps with a clock reading are (0: every stamp on it); below kPeriod / 2,
  // so that each edge's samples stay in order.
  std::int64_t stamp_jitter = 0;

  std::size_t frameCount() const { return names.size(); }
  // How long each buffer keeps an edge's history: that of a dynamic edge, so that every insert
  // past it drops the edge's oldest sample.
  std::int64_t history() const { return static_cast<std::int64_t>(samples) * kPeriod; }
  std::int64_t stamp(const Edge& edge, std::size_t k) const {
    return edge.first_stamp + static_cast<std::int64_t>(k) * kPeriod + jitterOf(edge, k);
  }
  // How far sample `k` of `edge` is stamped off its period: up to stamp_jitter either way, the
  // same in every run.
  std::int64_t jitterOf(const Edge& edge, std::size_t k) const {
    if (stamp_jitter == 0) return 0;
    const std::uint64_t mixed =
        (static_cast<std::uint64_t>(k) + 1) * 0x9e3779b97f4a7c15ull ^
        static_cast<std::uint64_t>(edge.first_stamp) * 0xbf58476d1ce4e5b9ull;
    const auto span = static_cast<std::uint64_t>(2 * stamp_jitter + 1);
    return static_cast<std::int64_t>((mixed >> 17) % span) - stamp_jitter;
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
  // Edges between two frames of one tree and how many of them are dynamic.
  std::pair<std::size_t, std::size_t> pathLength(std::size_t a, std::size_t b) const {
    std::size_t total = 0;
    std::size_t dynamic = 0;
    while (a != b) {
      std::size_t& deeper = depth[a] >= depth[b] ? a : b;
      ++total;
      dynamic += edges[edgeInto(deeper)].dynamic ? 1 : 0;
      deeper = parent[deeper];
    }
    return {total, dynamic};
  }
  std::size_t edgeInto(std::size_t frame) const { return edge_of_frame[frame]; }
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

// Adds a frame; `parent` is the frame's own index for a root.
inline std::size_t addFrame(Workload& w, std::size_t parent, std::string name) {
  const std::size_t id = w.names.size();
  const bool is_root = parent == id;
  w.names.push_back(std::move(name));
  w.parent.push_back(parent);
  w.depth.push_back(is_root ? 0 : w.depth[parent] + 1);
  w.root.push_back(is_root ? id : w.root[parent]);
  return id;
}

// An edge into every frame that is not a root, `dynamic_fraction` of them (shuffled) moving at
// 100 Hz with `w.samples` samples each, the rest static.
inline void buildMotion(Workload& w, std::mt19937_64& rng, double dynamic_fraction) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::size_t> children;
  for (std::size_t frame = 0; frame < w.frameCount(); ++frame) {
    if (w.parent[frame] != frame) children.push_back(frame);
  }
  std::vector<bool> dynamic(children.size(), false);
  const auto moving = static_cast<std::size_t>(
      std::ceil(dynamic_fraction * static_cast<double>(children.size()) - 1e-9));
  std::fill(dynamic.begin(), dynamic.begin() + static_cast<std::ptrdiff_t>(moving), true);
  std::shuffle(dynamic.begin(), dynamic.end(), rng);
  constexpr double kTwoPi = 6.283185307179586;
  w.edge_of_frame.assign(w.frameCount(), 0);
  for (std::size_t i = 0; i < children.size(); ++i) {
    Edge edge;
    edge.child = children[i];
    edge.parent = w.parent[edge.child];
    edge.dynamic = dynamic[i];
    w.edge_of_frame[edge.child] = w.edges.size();
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
    edge.samples.reserve(w.samples);
    for (std::size_t k = 0; k < w.samples; ++k) {
      const double t = static_cast<double>(k * Workload::kPeriod) * 1e-6;
      const double wave = std::sin(kTwoPi * frequency * t + phase);
      const Pose motion =
          poseOf(amplitude * wave, 0.5 * amplitude * wave, 0.0, ax, ay, az, swing * wave);
      edge.samples.push_back(perturb(base, motion));
    }
    w.edges.push_back(std::move(edge));
  }
}

// Random pairs of frames of one tree at random times where every edge has data, and the same
// times between frame 0 and the deepest frame of its tree.
inline void buildQueries(Workload& w, std::mt19937_64& rng) {
  w.oldest_common = Workload::kEpoch;
  w.newest_common = Workload::kEpoch + Workload::kPeriod;
  bool first = true;
  for (const Edge& e : w.edges) {
    if (!e.dynamic) continue;
    w.oldest_common = first ? w.stamp(e, 0) : std::max(w.oldest_common, w.stamp(e, 0));
    w.newest_common =
        first ? w.stamp(e, w.samples - 1) : std::min(w.newest_common, w.stamp(e, w.samples - 1));
    first = false;
  }
  w.deepest = 0;
  for (std::size_t frame = 0; frame < w.frameCount(); ++frame) {
    if (w.root[frame] == 0 && w.depth[frame] > w.depth[w.deepest]) w.deepest = frame;
  }
  std::vector<std::vector<std::size_t>> members(w.frameCount());
  for (std::size_t frame = 0; frame < w.frameCount(); ++frame) {
    members[w.root[frame]].push_back(frame);
  }
  std::uniform_int_distribution<std::int64_t> time(w.oldest_common, w.newest_common);
  std::uniform_int_distribution<std::size_t> frame(0, w.frameCount() - 1);
  while (w.random_pairs.size() < Workload::kQueries) {
    Query q;
    q.target = frame(rng);
    const std::vector<std::size_t>& tree = members[w.root[q.target]];
    if (tree.size() < 2) continue;
    std::uniform_int_distribution<std::size_t> member(0, tree.size() - 1);
    do {
      q.source = tree[member(rng)];
    } while (q.source == q.target);
    q.time = time(rng);
    q.other_time = time(rng);
    q.fixed = w.root[q.target];
    w.random_pairs.push_back(q);
    const bool up = w.deepest_chain.size() % 2 == 0;
    w.deepest_chain.push_back(Query{up ? 0 : w.deepest, up ? w.deepest : 0, q.time, q.other_time});
  }
}

}  // namespace detail

// The pose of a dynamic edge that inserts at `step` give: they cycle through each edge's first few,
// so that reading them costs a benchmark little beside the library's work, whatever the size of the
// workload.
inline const Pose& insertedPose(const Edge& edge, std::size_t step) {
  constexpr std::size_t kPoses = 8;
  return edge.samples[step % std::min(kPoses, edge.samples.size())];
}

inline std::vector<std::size_t> dynamicEdges(const Workload& w) {
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < w.edges.size(); ++i) {
    if (w.edges[i].dynamic) indices.push_back(i);
  }
  return indices;
}

// Gives `subject` (anything with set(edge, utime, pose, is_static)) the first sample of each
// edge in the order the frames were made, then the rest of the history of every dynamic edge,
// one sample of each in turn.
template <class Subject>
void fill(Subject& subject, const Workload& w) {
  for (std::size_t i = 0; i < w.edges.size(); ++i) {
    const Edge& edge = w.edges[i];
    if (edge.dynamic) {
      subject.set(i, w.stamp(edge, 0), edge.samples[0]);
    } else {
      subject.set(i, w.oldest_common, edge.samples[0], true);
    }
  }
  const std::vector<std::size_t> dynamic = dynamicEdges(w);
  for (std::size_t k = 1; k < w.samples; ++k) {
    for (std::size_t i : dynamic) subject.set(i, w.stamp(w.edges[i], k), w.edges[i].samples[k]);
  }
}

}  // namespace bench
