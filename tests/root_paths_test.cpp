#include "root_paths.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace lcmtf {
namespace {

constexpr std::int64_t kCacheTime = 10'000'000;
constexpr std::int64_t kFirstStamp = 1000;

using Hops = std::vector<FrameId>;

// Frames as the buffer keeps them, built by hand: record 0 stands for no frame, and a frame's
// static chain is either its own single static edge or continues its parent's.
struct Frames {
  Frames() { add(""); }

  FrameId add(const std::string& name) {
    names.push_back(name);
    const auto id = static_cast<FrameId>(records.size());
    FrameRecord& record = records.emplace_back();
    record.name = names.back();
    record.static_top = id;
    return id;
  }

  /// A dynamic edge from `child` to `parent`, sampled at `stamp`.
  void attach(FrameId child, FrameId parent, std::int64_t stamp = kFirstStamp) {
    records[child].cache.insert(detail::EdgeSample{stamp, parent, offsetOf(child)}, kCacheTime);
  }
  /// A newer sample of `child`'s dynamic edge, under `parent`.
  void reparent(FrameId child, FrameId parent) {
    attach(child, parent, records[child].cache.newestStamp() + 1);
  }
  /// A static edge that lookups cross alone.
  void attachStatic(FrameId child, FrameId parent) {
    records[child].cache.setStatic(parent, offsetOf(child));
  }
  /// A static edge continuing the static chain of `parent`, whose own chain is in place.
  void attachStaticChained(FrameId child, FrameId parent) {
    attachStatic(child, parent);
    continueStaticChain(records[child], records[parent], offsetOf(child));
  }

  static Transform offsetOf(FrameId frame) {
    return Transform(Eigen::Vector3d(frame, 1.0, 0.0),
                     Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * frame, Eigen::Vector3d::UnitZ())));
  }

  std::deque<std::string> names;  // stable storage for the records' names
  FrameTable records;
};

// Where each step of `frame`'s path ends, or nothing when the frame has no path.
std::optional<Hops> hopsOf(const FrameTable& frames, const RootPaths& paths, FrameId frame) {
  RootPaths::Path path;
  if (!paths.find(frames, frame, path)) return std::nullopt;
  Hops hops;
  for (std::uint32_t i = 0; i < path.size; ++i) hops.push_back(path.steps[i].next);
  return hops;
}

FrameId rootOf(const FrameTable& frames, const RootPaths& paths, FrameId frame) {
  RootPaths::Path path;
  return paths.find(frames, frame, path) ? path.root : kNoFrame;
}

// The steps up from `frame` taken one stepFrom() at a time; nothing when they go round a loop.
std::optional<std::vector<RootStep>> climbFrom(const FrameTable& frames, FrameId frame) {
  std::vector<RootStep> steps;
  for (RootStep step = stepFrom(frames, frame); step.next != kNoFrame;
       step = stepFrom(frames, step.next)) {
    steps.push_back(step);
    if (steps.size() > frames.size()) return std::nullopt;
  }
  return steps;
}

::testing::AssertionResult sameStep(const RootStep& actual, const RootStep& expected) {
  if (actual.cache == expected.cache && actual.fixed == expected.fixed &&
      actual.child == expected.child && actual.parent == expected.parent &&
      actual.next == expected.next && actual.anchor == expected.anchor) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "step " << actual.child << " -> " << actual.parent << " (to " << actual.next
         << (actual.anchored() ? ", anchored" : "") << "), expected " << expected.child << " -> "
         << expected.parent << " (to " << expected.next << (expected.anchored() ? ", anchored" : "")
         << ")";
}

void expectLinksUpToItsRoot(const FrameTable& frames, FrameId frame, const RootPaths::Path& path) {
  if (path.size == 0) {
    EXPECT_EQ(path.root, frame);
  } else {
    EXPECT_EQ(path.steps[0].child, frame);
    for (std::uint32_t i = 0; i + 1 < path.size; ++i) {
      EXPECT_EQ(path.steps[i].next, path.steps[i + 1].child) << "after step " << i;
    }
    EXPECT_EQ(path.steps[path.size - 1].next, path.root);
  }
  EXPECT_EQ(stepFrom(frames, path.root).next, kNoFrame) << "the root has a parent";
}

// Every frame has the path that climbing one step at a time gives, linked up to its root, or
// none when the climb loops or is longer than the longest path kept.
void expectPathsMatchClimbs(const FrameTable& frames, const RootPaths& paths) {
  EXPECT_EQ(paths.frameCount(), frames.size());
  for (FrameId frame = 1; frame < frames.size(); ++frame) {
    SCOPED_TRACE("frame " + std::string(frames[frame].name));
    const std::optional<std::vector<RootStep>> climb = climbFrom(frames, frame);
    const bool usable = climb && climb->size() <= RootPaths::kLongestPath;
    RootPaths::Path path;
    ASSERT_EQ(paths.find(frames, frame, path), usable);
    if (!usable) continue;
    ASSERT_EQ(path.size, climb->size());
    for (std::uint32_t i = 0; i < path.size; ++i) {
      EXPECT_TRUE(sameStep(path.steps[i], (*climb)[i])) << "step " << i;
    }
    expectLinksUpToItsRoot(frames, frame, path);
  }
}

void rebuildAndCheck(const FrameTable& frames, RootPaths& paths) {
  paths.rebuild(frames);
  expectPathsMatchClimbs(frames, paths);
}

TEST(RootPaths, EveryFramesStepsLinkUpToItsRoot) {
  Frames f;
  const FrameId world = f.add("world");
  const FrameId map = f.add("map");
  const FrameId odom = f.add("odom");
  const FrameId base = f.add("base");
  const FrameId laser = f.add("laser");
  const FrameId camera = f.add("camera");
  const FrameId sun = f.add("sun");
  const FrameId planet = f.add("planet");
  const FrameId lonely = f.add("lonely");
  f.attach(laser, base);
  f.attach(map, world);
  f.attach(odom, map);
  f.attach(base, odom);
  f.attachStatic(camera, base);
  f.attach(planet, sun);
  RootPaths paths;
  rebuildAndCheck(f.records, paths);
  EXPECT_EQ(hopsOf(f.records, paths, world), Hops{});
  EXPECT_EQ(hopsOf(f.records, paths, map), (Hops{world}));
  EXPECT_EQ(hopsOf(f.records, paths, base), (Hops{odom, map, world}));
  EXPECT_EQ(hopsOf(f.records, paths, laser), (Hops{base, odom, map, world}));
  EXPECT_EQ(hopsOf(f.records, paths, camera), (Hops{base, odom, map, world}));
  EXPECT_EQ(hopsOf(f.records, paths, planet), (Hops{sun}));
  EXPECT_EQ(hopsOf(f.records, paths, lonely), Hops{});
  EXPECT_EQ(rootOf(f.records, paths, camera), world);
  EXPECT_EQ(rootOf(f.records, paths, planet), sun);
  EXPECT_EQ(rootOf(f.records, paths, lonely), lonely);
}

TEST(RootPaths, FramesOnOrBelowALoopHaveNoPath) {
  Frames f;
  const FrameId below_settled_first = f.add("below_settled_first");
  const FrameId a = f.add("a");
  const FrameId b = f.add("b");
  const FrameId c = f.add("c");
  const FrameId under = f.add("under");
  const FrameId self = f.add("self");
  const FrameId below_self = f.add("below_self");
  const FrameId static_p = f.add("static_p");
  const FrameId static_q = f.add("static_q");
  const FrameId below_static = f.add("below_static");
  const FrameId mixed_m = f.add("mixed_m");
  const FrameId mixed_n = f.add("mixed_n");
  const FrameId world = f.add("world");
  const FrameId rover = f.add("rover");
  f.attach(a, b);
  f.attach(b, c);
  f.attach(c, a);
  f.attach(below_settled_first, a);
  f.attach(under, below_settled_first);
  f.attach(self, self);
  f.attach(below_self, self);
  f.attachStatic(static_p, static_q);
  f.attachStatic(static_q, static_p);
  f.attach(below_static, static_p);
  f.attach(mixed_m, mixed_n);
  f.attachStatic(mixed_n, mixed_m);
  f.attach(rover, world);
  RootPaths paths;
  rebuildAndCheck(f.records, paths);
  for (const FrameId looped : {below_settled_first, a, b, c, under, self, below_self, static_p,
                               static_q, below_static, mixed_m, mixed_n}) {
    EXPECT_EQ(hopsOf(f.records, paths, looped), std::nullopt) << f.records[looped].name;
  }
  EXPECT_EQ(hopsOf(f.records, paths, rover), (Hops{world}));
  EXPECT_EQ(hopsOf(f.records, paths, world), Hops{});
}

TEST(RootPaths, PathsLongerThanTheLongestAreNotUsable) {
  constexpr std::uint32_t kChainLength = RootPaths::kLongestPath + 3;
  for (const bool root_first : {true, false}) {
    SCOPED_TRACE(root_first ? "root added first" : "root added last");
    Frames f;
    for (std::uint32_t i = 0; i < kChainLength; ++i) f.add("link" + std::to_string(i));
    const auto depthOf = [&](FrameId frame) {
      return root_first ? frame - 1 : kChainLength - frame;
    };
    for (FrameId frame = 1; frame <= kChainLength; ++frame) {
      if (depthOf(frame) > 0) f.attach(frame, root_first ? frame - 1 : frame + 1);
    }
    RootPaths paths;
    rebuildAndCheck(f.records, paths);
    for (FrameId frame = 1; frame <= kChainLength; ++frame) {
      const std::optional<Hops> hops = hopsOf(f.records, paths, frame);
      if (depthOf(frame) <= RootPaths::kLongestPath) {
        ASSERT_TRUE(hops) << "depth " << depthOf(frame);
        EXPECT_EQ(hops->size(), depthOf(frame));
      } else {
        EXPECT_FALSE(hops) << "depth " << depthOf(frame);
      }
    }
  }
}

// Both find a path for the same frames, with the same steps.
void expectSamePaths(const FrameTable& frames, const RootPaths& actual, const RootPaths& expected) {
  for (FrameId frame = 1; frame < frames.size(); ++frame) {
    SCOPED_TRACE("frame " + std::string(frames[frame].name));
    RootPaths::Path path;
    RootPaths::Path expected_path;
    const bool found = expected.find(frames, frame, expected_path);
    ASSERT_EQ(actual.find(frames, frame, path), found);
    if (!found) continue;
    EXPECT_EQ(path.root, expected_path.root);
    ASSERT_EQ(path.size, expected_path.size);
    for (std::uint32_t i = 0; i < path.size; ++i) {
      EXPECT_TRUE(sameStep(path.steps[i], expected_path.steps[i])) << "step " << i;
    }
  }
}

TEST(RootPaths, ExtendGivesNewFramesThePathsARebuildGives) {
  Frames f;
  const FrameId world = f.add("world");
  const FrameId map = f.add("map");
  const FrameId base = f.add("base");
  const FrameId laser = f.add("laser");
  f.attach(map, world);
  f.attach(base, map);
  f.attachStaticChained(laser, base);
  RootPaths paths;
  paths.rebuild(f.records);

  const FrameId tool = f.add("tool");  // below a frame added after it
  const FrameId arm = f.add("arm");
  const FrameId hand = f.add("hand");
  const FrameId finger = f.add("finger");
  const FrameId wrist = f.add("wrist");
  const FrameId dock = f.add("dock");
  const FrameId charger = f.add("charger");
  const FrameId x = f.add("x");
  const FrameId y = f.add("y");
  const FrameId below_loop = f.add("below_loop");
  f.attach(arm, base);
  f.attachStaticChained(hand, arm);
  f.attach(finger, hand);
  f.attach(wrist, hand);
  f.attach(tool, wrist);
  f.attach(charger, dock);
  f.attach(x, y);
  f.attach(y, x);
  f.attach(below_loop, x);
  ASSERT_TRUE(paths.canExtendTo(f.records));
  paths.extend(f.records);
  RootPaths rebuilt;
  rebuilt.rebuild(f.records);
  expectSamePaths(f.records, paths, rebuilt);
  expectPathsMatchClimbs(f.records, paths);
  EXPECT_EQ(hopsOf(f.records, paths, finger), (Hops{arm, base, map, world}));
  EXPECT_EQ(hopsOf(f.records, paths, tool), (Hops{wrist, arm, base, map, world}));
  EXPECT_EQ(hopsOf(f.records, paths, below_loop), std::nullopt);

  const FrameId cable = f.add("cable");
  f.attach(cable, charger);
  ASSERT_TRUE(paths.canExtendTo(f.records));
  paths.extend(f.records);
  rebuilt.rebuild(f.records);
  expectSamePaths(f.records, paths, rebuilt);
  expectPathsMatchClimbs(f.records, paths);
  EXPECT_EQ(hopsOf(f.records, paths, cable), (Hops{charger, dock}));
}

TEST(RootPaths, AddingFramesLeavesRecordsInPlaceSoPathsExtend) {
  Frames f;
  const FrameId world = f.add("world");
  const FrameId base = f.add("base");
  f.attach(base, world);
  RootPaths paths;
  paths.rebuild(f.records);
  const FrameRecord* const before = &f.records[base];
  std::vector<FrameId> added;
  for (int i = 0; i < 5000; ++i) {
    added.push_back(f.add("extra_" + std::to_string(i)));
    f.attach(added.back(), base);
  }
  EXPECT_EQ(&f.records[base], before);
  ASSERT_TRUE(paths.canExtendTo(f.records));
  paths.extend(f.records);
  EXPECT_EQ(hopsOf(f.records, paths, base), (Hops{world}));
  EXPECT_EQ(hopsOf(f.records, paths, added.back()), (Hops{base, world}));
  expectPathsMatchClimbs(f.records, paths);
}

TEST(RootPaths, PathsBuiltForAnotherTableAreNotFound) {
  Frames f;
  Frames other;
  const FrameId world = f.add("world");
  const FrameId base = f.add("base");
  other.add("world");
  other.add("base");
  f.attach(base, world);
  RootPaths paths;
  paths.rebuild(f.records);
  EXPECT_FALSE(paths.canExtendTo(other.records));
  RootPaths::Path path;
  EXPECT_FALSE(paths.find(other.records, base, path));
  EXPECT_TRUE(paths.find(f.records, base, path));
}

TEST(RootPaths, RebuiltPathsFollowAReparentedEdge) {
  Frames f;
  const FrameId world = f.add("world");
  const FrameId a = f.add("a");
  const FrameId b = f.add("b");
  const FrameId c = f.add("c");
  const FrameId d = f.add("d");
  const FrameId elsewhere = f.add("elsewhere");
  f.attach(a, world);
  f.attach(b, world);
  f.attach(c, a);
  f.attach(d, c);
  RootPaths paths;
  paths.rebuild(f.records);
  ASSERT_EQ(hopsOf(f.records, paths, d), (Hops{c, a, world}));

  f.reparent(c, b);
  rebuildAndCheck(f.records, paths);
  EXPECT_EQ(hopsOf(f.records, paths, c), (Hops{b, world}));
  EXPECT_EQ(hopsOf(f.records, paths, d), (Hops{c, b, world}));

  f.reparent(b, elsewhere);
  rebuildAndCheck(f.records, paths);
  EXPECT_EQ(hopsOf(f.records, paths, d), (Hops{c, b, elsewhere}));
  EXPECT_EQ(rootOf(f.records, paths, d), elsewhere);
  EXPECT_EQ(hopsOf(f.records, paths, a), (Hops{world}));
}

TEST(RootPaths, RebuiltPathsFollowEdgesIntoAndOutOfALoop) {
  Frames f;
  const FrameId world = f.add("world");
  const FrameId x = f.add("x");
  const FrameId y = f.add("y");
  const FrameId z = f.add("z");
  f.attach(x, world);
  f.attach(y, x);
  f.attach(z, y);
  RootPaths paths;
  paths.rebuild(f.records);
  ASSERT_EQ(hopsOf(f.records, paths, z), (Hops{y, x, world}));

  f.reparent(x, y);
  rebuildAndCheck(f.records, paths);
  for (const FrameId looped : {x, y, z}) {
    EXPECT_EQ(hopsOf(f.records, paths, looped), std::nullopt) << f.records[looped].name;
  }

  f.reparent(y, world);
  rebuildAndCheck(f.records, paths);
  EXPECT_EQ(hopsOf(f.records, paths, y), (Hops{world}));
  EXPECT_EQ(hopsOf(f.records, paths, x), (Hops{y, world}));
  EXPECT_EQ(hopsOf(f.records, paths, z), (Hops{y, world}));
}

TEST(RootPaths, DynamicStepIntoAStaticChainIsAnchored) {
  Frames f;
  const FrameId world = f.add("world");
  const FrameId base = f.add("base");
  const FrameId mount = f.add("mount");
  const FrameId sensor = f.add("sensor");
  const FrameId target = f.add("target");
  const FrameId probe = f.add("probe");
  const FrameId lone_static = f.add("lone_static");
  const FrameId follower = f.add("follower");
  f.attach(base, world);
  f.attachStaticChained(mount, base);
  f.attachStaticChained(sensor, mount);
  f.attach(target, sensor);
  f.attach(probe, base);
  f.attachStatic(lone_static, world);
  f.attach(follower, lone_static);
  RootPaths paths;
  rebuildAndCheck(f.records, paths);
  const auto& records = f.records;
  RootPaths::Path path;

  ASSERT_TRUE(paths.find(records, target, path));
  ASSERT_EQ(path.size, 2u);
  EXPECT_EQ(path.steps[0].cache, &records[target].cache);
  EXPECT_EQ(path.steps[0].parent, sensor);
  EXPECT_EQ(path.steps[0].next, base);
  EXPECT_TRUE(path.steps[0].anchored());
  EXPECT_EQ(path.steps[1].cache, &records[base].cache);
  EXPECT_FALSE(path.steps[1].anchored());

  ASSERT_TRUE(paths.find(records, sensor, path));
  ASSERT_EQ(path.size, 2u);
  EXPECT_EQ(path.steps[0].fixed, &records[sensor].static_top_T_frame);
  EXPECT_EQ(path.steps[0].cache, nullptr);
  EXPECT_EQ(path.steps[0].next, base);

  ASSERT_TRUE(paths.find(records, probe, path));
  ASSERT_EQ(path.size, 2u);
  EXPECT_FALSE(path.steps[0].anchored());

  ASSERT_TRUE(paths.find(records, follower, path));
  ASSERT_EQ(path.size, 2u);
  EXPECT_FALSE(path.steps[0].anchored());
  EXPECT_EQ(path.steps[0].next, lone_static);
  EXPECT_EQ(path.steps[1].fixed, &records[lone_static].cache.staticTransform());
  EXPECT_EQ(path.steps[1].next, world);
}

}  // namespace
}  // namespace lcmtf
