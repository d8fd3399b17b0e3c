// BufferCore lookups stay right as the tree changes shape: edges appear, change parent, turn
// static or dynamic, close loops and are cleared. Each change is made to the buffer and to a
// plain model of the tree, and lookups between every pair of frames are checked against the
// model's answer, composed here edge by edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/exceptions.hpp"
#include "support/buffer_core_helpers.hpp"
#include "support/test_scale.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::near;

constexpr double kTolerance = 1e-9;

// The two stamps every dynamic edge has a sample at, and the times lookups are asked at.
constexpr double kOlder = 1.0;
constexpr double kNewer = 2.0;
constexpr double kBetween = 1.375;
constexpr double kRatio = (kBetween - kOlder) / (kNewer - kOlder);

// An edge as the test stored it: a static value, or two samples of a dynamic edge, each with
// its own value and possibly its own parent.
struct ModelEdge {
  std::string older_parent;
  std::string parent;  // the static edge's, or the newer sample's
  Eigen::Isometry3d older_value;
  Eigen::Isometry3d value;
  bool is_static = false;

  std::string parentAt(double time) const {
    return is_static || time >= kNewer ? parent : older_parent;
  }
  // Between two samples of one parent the translation is interpolated linearly and the
  // rotation along the shorter arc; between different parents the older sample holds.
  Eigen::Isometry3d valueAt(double time) const {
    if (is_static || time >= kNewer) return value;
    if (time <= kOlder || older_parent != parent) return older_value;
    const Eigen::Quaterniond older(older_value.linear());
    const Eigen::Quaterniond newer(value.linear());
    Eigen::Isometry3d mixed = Eigen::Isometry3d::Identity();
    mixed.linear() = older.slerp(kRatio, newer).toRotationMatrix();
    mixed.translation() = (1 - kRatio) * older_value.translation() + kRatio * value.translation();
    return mixed;
  }
};

struct Answer {
  Eigen::Isometry3d value;
  bool any_dynamic = false;
};

// The tree as the test built it, at the two times lookups are asked at.
class TreeModel {
 public:
  std::map<std::string, ModelEdge> edges;  // by child

  std::string describe() const {
    std::string text;
    for (const auto& [child, edge] : edges) {
      text += " " + child + (edge.is_static ? " -static-> " : " -> ") + edge.parent;
      if (!edge.is_static && edge.older_parent != edge.parent) {
        text += " (before " + std::to_string(kNewer) + ": -> " + edge.older_parent + ")";
      }
      text += ";";
    }
    return text;
  }

  // target_T_source at `time`, or nothing when the frames are not connected or a loop is
  // climbed before they meet. As in tf, the source climbs first and stops at the target if it
  // reaches it, and a frame in itself is the identity.
  std::optional<Answer> lookup(const std::string& target, const std::string& source,
                               double time) const {
    if (target == source) return Answer{Eigen::Isometry3d::Identity(), false};
    const auto up_from_source = climb(source, target, time);
    if (!up_from_source) return std::nullopt;
    const Step& top = up_from_source->back();
    if (top.frame == target) return Answer{top.frame_T_start, top.any_dynamic};
    const auto up_from_target = climb(target, target, time);
    if (!up_from_target) return std::nullopt;
    for (const Step& from_target : *up_from_target) {
      for (const Step& from_source : *up_from_source) {
        if (from_source.frame != from_target.frame) continue;
        return Answer{from_target.frame_T_start.inverse() * from_source.frame_T_start,
                      from_target.any_dynamic || from_source.any_dynamic};
      }
    }
    return std::nullopt;
  }

 private:
  struct Step {
    std::string frame;
    Eigen::Isometry3d frame_T_start;
    bool any_dynamic;
  };

  std::optional<std::vector<Step>> climb(const std::string& start, const std::string& stop,
                                         double time) const {
    std::vector<Step> steps{{start, Eigen::Isometry3d::Identity(), false}};
    for (;;) {
      if (steps.size() > 1 && steps.back().frame == stop) return steps;
      const auto edge = edges.find(steps.back().frame);
      if (edge == edges.end()) return steps;
      if (steps.size() > edges.size()) return std::nullopt;
      const Step& below = steps.back();
      steps.push_back({edge->second.parentAt(time),
                       edge->second.valueAt(time) * below.frame_T_start,
                       below.any_dynamic || !edge->second.is_static});
    }
  }
};

class TreeChanges : public ::testing::Test {
 protected:
  BufferCore buffer;
  TreeModel model;
  std::mt19937_64 random{7};
  std::size_t time_travel_checks = 0;
  std::vector<std::string> names{"map",  "odom", "base",   "torso", "arm",
                                 "hand", "tip",  "camera", "lens",  "cup"};

  Eigen::Isometry3d randomPose() {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const Eigen::Vector3d axis(unit(random), unit(random), unit(random) + 2.0);
    return lcmtf_test::isometry({unit(random), unit(random), unit(random)}, 3.0 * unit(random),
                                axis);
  }

  static Transform transformOf(const Eigen::Isometry3d& value) {
    return Transform(value.translation(), Eigen::Quaterniond(value.linear()));
  }

  // A static edge, or a dynamic one with a sample of its own value at each stamp, the older
  // one under `older_parent` when given.
  void setEdge(const std::string& parent, const std::string& child, bool is_static,
               const std::string& older_parent = "") {
    ModelEdge edge{older_parent.empty() ? parent : older_parent, parent, randomPose(), randomPose(),
                   is_static};
    if (is_static) {
      lcmtf_test::putStatic(buffer, parent, child, transformOf(edge.value));
    } else {
      lcmtf_test::put(buffer, edge.older_parent, child, at(kOlder), transformOf(edge.older_value));
      lcmtf_test::put(buffer, parent, child, at(kNewer), transformOf(edge.value));
    }
    model.edges[child] = edge;
  }

  void clear() {
    buffer.clear();
    for (auto edge = model.edges.begin(); edge != model.edges.end();) {
      edge = edge->second.is_static ? std::next(edge) : model.edges.erase(edge);
    }
  }

  // Every ordered pair of known frames, at a time between the samples and at the latest.
  void expectLookupsMatchTheModel(const std::string& after) {
    for (const std::string& target : names) {
      for (const std::string& source : names) {
        if (target == source || !buffer.frameExists(target) || !buffer.frameExists(source)) {
          continue;
        }
        const std::string what =
            after + ": " + source + " in " + target + ", in the tree" + model.describe();
        expectLookupMatches(target, source, at(kBetween), model.lookup(target, source, kBetween),
                            what + ", between the samples");
        // The latest common time is found in the tree as of the newest samples, which every
        // dynamic edge has at kNewer: it is kNewer, or no time when only static edges are met.
        std::optional<Answer> latest = model.lookup(target, source, kNewer);
        expectLookupMatches(target, source, kLatestTime, latest, what + ", at the latest");
        if (latest) {
          EXPECT_EQ(buffer.lookupTransform(target, source, kLatestTime).stamp,
                    latest->any_dynamic ? at(kNewer) : kLatestTime)
              << what;
        }
      }
    }
    expectTimeTravelMatchesTheModel(after);
  }

  void expectLookupMatches(const std::string& target, const std::string& source, TimePoint time,
                           const std::optional<Answer>& expected, const std::string& what) {
    EXPECT_EQ(buffer.canTransform(target, source, time), expected.has_value()) << what;
    if (!expected) {
      EXPECT_THROW(buffer.lookupTransform(target, source, time), TransformException) << what;
      return;
    }
    EXPECT_TRUE(
        near(buffer.lookupTransform(target, source, time).transform, expected->value, kTolerance))
        << what;
  }

  // Every ordered pair through a third of the frames as the fixed frame (another third after
  // each change; in the slower builds a smaller share), the source at a time between the
  // samples and the target at the newer one.
  void expectTimeTravelMatchesTheModel(const std::string& after) {
    ++time_travel_checks;
    for (const std::string& target : names) {
      for (const std::string& source : names) {
        const std::size_t stride = 3 * lcmtf_test::kWorkDivisor;
        for (std::size_t f = time_travel_checks % stride; f < names.size(); f += stride) {
          const std::string& fixed = names[f];
          if (!buffer.frameExists(target) || !buffer.frameExists(source) ||
              !buffer.frameExists(fixed)) {
            continue;
          }
          const std::optional<Answer> fixed_T_source = model.lookup(fixed, source, kBetween);
          const std::optional<Answer> target_T_fixed = model.lookup(target, fixed, kNewer);
          const std::string what = after + ": " + source + " in " + target + " through " + fixed +
                                   ", in the tree" + model.describe();
          if (!fixed_T_source || !target_T_fixed) {
            EXPECT_THROW(buffer.lookupTransform(target, at(kNewer), source, at(kBetween), fixed),
                         TransformException)
                << what;
            continue;
          }
          const TransformStamped travelled =
              buffer.lookupTransform(target, at(kNewer), source, at(kBetween), fixed);
          EXPECT_TRUE(
              near(travelled.transform, target_T_fixed->value * fixed_T_source->value, kTolerance))
              << what;
          EXPECT_EQ(travelled.stamp, at(kNewer)) << what;
        }
      }
    }
  }
};

TEST_F(TreeChanges, FrameGivenAParentAfterItsChildrenJoinsTheTree) {
  setEdge("arm", "hand", false);
  setEdge("hand", "tip", true);
  setEdge("base", "camera", true);
  expectLookupsMatchTheModel("two trees");
  setEdge("base", "arm", false);
  expectLookupsMatchTheModel("arm joined under base");
}

TEST_F(TreeChanges, ReparentedEdgeIsFollowedToItsNewParent) {
  setEdge("map", "odom", true);
  setEdge("odom", "base", false);
  setEdge("base", "arm", true);
  setEdge("arm", "hand", false);
  setEdge("map", "cup", false);
  expectLookupsMatchTheModel("cup on the map");
  setEdge("hand", "cup", false);
  expectLookupsMatchTheModel("cup picked up");
  setEdge("map", "cup", false);
  expectLookupsMatchTheModel("cup put down");
}

TEST_F(TreeChanges, EdgeTurnedStaticOrDynamicKeepsItsPlaceInTheTree) {
  setEdge("map", "odom", true);
  setEdge("odom", "base", true);
  setEdge("base", "camera", false);
  setEdge("camera", "lens", true);
  expectLookupsMatchTheModel("start");
  setEdge("odom", "base", false);
  expectLookupsMatchTheModel("base now dynamic");
  setEdge("base", "camera", true);
  expectLookupsMatchTheModel("camera now static");
  setEdge("odom", "base", true);
  expectLookupsMatchTheModel("base static again");
}

TEST_F(TreeChanges, LoopIsRefusedUntilItIsBroken) {
  setEdge("map", "odom", true);
  setEdge("odom", "base", false);
  setEdge("base", "arm", true);
  setEdge("arm", "hand", false);
  setEdge("hand", "odom", false);
  expectLookupsMatchTheModel("loop odom-base-arm-hand");
  setEdge("map", "odom", false);
  expectLookupsMatchTheModel("loop broken");
}

TEST_F(TreeChanges, ClearLeavesTheStaticEdgesToLookUp) {
  setEdge("map", "odom", true);
  setEdge("odom", "base", false);
  setEdge("base", "arm", true);
  setEdge("arm", "hand", true);
  clear();
  expectLookupsMatchTheModel("cleared");
  setEdge("map", "base", false);
  expectLookupsMatchTheModel("base under map after the clear");
}

TEST_F(TreeChanges, TreeGrownEdgeByEdgeInAnyOrderIsLookedUpRight) {
  // A random tree of 40 frames whose edges arrive shuffled, children often before parents.
  names.clear();
  std::vector<std::pair<std::string, std::string>> edges;
  for (int frame = 0; frame < 40; ++frame) {
    names.push_back("link_" + std::to_string(frame));
    if (frame == 0) continue;
    const int parent =
        std::uniform_int_distribution<int>(std::max(0, frame - 6), frame - 1)(random);
    edges.emplace_back(names[static_cast<std::size_t>(parent)], names.back());
  }
  std::shuffle(edges.begin(), edges.end(), random);
  // Checking every pair after each edge costs 40² lookups; the slower builds check less often.
  const std::size_t check_every = 4 * lcmtf_test::kWorkDivisor;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    setEdge(edges[i].first, edges[i].second, i % 3 == 0);
    if (i % check_every == check_every - 1 || i + 1 == edges.size()) {
      expectLookupsMatchTheModel("after edge " + std::to_string(i));
    }
    if (HasFailure()) break;
  }
}

TEST_F(TreeChanges, EdgeReparentedWithinItsHistoryIsFollowedAtEachTime) {
  setEdge("map", "odom", true);
  setEdge("odom", "base", false);
  setEdge("base", "hand", false);
  setEdge("hand", "cup", false, "map");
  expectLookupsMatchTheModel("cup picked up between the samples");
  setEdge("base", "camera", true);
  setEdge("map", "cup", false, "camera");
  expectLookupsMatchTheModel("cup handed from the camera mount to the map");
}

TEST_F(TreeChanges, LoopOnlyBetweenTheSamplesIsRefusedThereAndNotAtTheLatest) {
  setEdge("map", "odom", true);
  setEdge("odom", "base", false, "arm");
  setEdge("base", "arm", false);
  setEdge("arm", "hand", true);
  setEdge("arm", "camera", true);
  expectLookupsMatchTheModel("base under arm before the newer sample");
}

TEST_F(TreeChanges, RandomChangesKeepEveryLookupRight) {
  std::uniform_int_distribution<std::size_t> pick(0, names.size() - 1);
  std::uniform_int_distribution<int> change(0, 19);
  const int rounds = lcmtf_test::scaledCount(400);
  for (int round = 0; round < rounds; ++round) {
    const int kind = change(random);
    const std::string parent = names[pick(random)];
    const std::string child = names[pick(random)];
    const std::string older_parent = names[pick(random)];
    std::string after = "round " + std::to_string(round) + ": ";
    if (kind == 0) {
      clear();
      after += "clear";
    } else if (kind == 1) {
      buffer.resolveFrame(child);
      after += "resolved " + child;
    } else if (parent != child && kind % 4 == 3 && older_parent != child) {
      setEdge(parent, child, false, older_parent);
      after += older_parent + " then " + parent + " -> " + child + " dynamic";
    } else if (parent != child) {
      const bool is_static = kind % 2 == 0;
      setEdge(parent, child, is_static);
      after += parent + " -> " + child + (is_static ? " static" : " dynamic");
    }
    expectLookupsMatchTheModel(after);
    if (HasFailure()) break;
  }
}

// In a tree large enough that rebuilding every frame's root path takes a while, an edge that
// changes parent on every insert and a static edge that changes on every insert put the
// rebuilds off; lookups meanwhile must follow the tree as it is, not the paths last built.
TEST(TreeChangesInALargeTree, LookupsFollowEachChangeWhileRebuildsArePutOff) {
  BufferCore buffer;
  // A 4-ary tree of frames 0..2999: each static edge 1 m up z, but frame 1's, x_1 m along x.
  constexpr int kFrames = 3000;
  const auto name = [](int frame) { return "f" + std::to_string(frame); };
  const auto up = [](double z) {
    return Transform(Eigen::Vector3d(0, 0, z), Eigen::Quaterniond::Identity());
  };
  for (int frame = 1; frame < kFrames; ++frame) {
    lcmtf_test::putStatic(buffer, name((frame - 1) / 4), name(frame), up(1.0));
  }
  // f2999's root path: 2999 -> 749 -> 187 -> 46 -> 11 -> 2 -> 0, so it hangs below f2.
  const int deep_under_1 = 1365;  // 1365 -> 341 -> 85 -> 21 -> 5 -> 1 -> 0
  const int rounds = lcmtf_test::scaledCount(400);
  for (int k = 0; k < rounds; ++k) {
    const double x_1 = 0.5 + 0.001 * k;
    lcmtf_test::putStatic(buffer, name(0), name(1),
                          Transform(Eigen::Vector3d(x_1, 0, 0), Eigen::Quaterniond::Identity()));
    const bool under_1 = k % 2 == 0;
    lcmtf_test::put(buffer, under_1 ? name(1) : name(2), "mover", at(0.001 * k), up(0.25));
    const Transform mover = buffer.lookupTransform(name(0), "mover", kLatestTime).transform;
    const Eigen::Vector3d expected_mover =
        under_1 ? Eigen::Vector3d(x_1, 0, 0.25) : Eigen::Vector3d(0, 0, 1.25);
    ASSERT_LT((mover.translation - expected_mover).norm(), kTolerance) << "round " << k;
    const Transform deep =
        buffer.lookupTransform(name(0), name(deep_under_1), kLatestTime).transform;
    ASSERT_LT((deep.translation - Eigen::Vector3d(x_1, 0, 5.0)).norm(), kTolerance)
        << "round " << k;
    const Transform across = buffer.lookupTransform("mover", name(2999), kLatestTime).transform;
    const Eigen::Vector3d f0_f2999(0, 0, 6.0);
    ASSERT_LT((across.translation - (f0_f2999 - expected_mover)).norm(), kTolerance)
        << "round " << k;
  }
}

}  // namespace
}  // namespace lcmtf
