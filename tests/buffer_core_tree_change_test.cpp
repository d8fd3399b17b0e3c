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

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::near;

constexpr double kTolerance = 1e-9;

struct ModelEdge {
  std::string parent;
  Eigen::Isometry3d parent_T_child;
  bool is_static = false;
};

struct Answer {
  Eigen::Isometry3d value;
  bool any_dynamic = false;
};

// The tree as the test built it. Dynamic edges hold one value at two stamps, so that a lookup
// at any time between them has a single right answer.
class TreeModel {
 public:
  std::map<std::string, ModelEdge> edges;  // by child

  std::string describe() const {
    std::string text;
    for (const auto& [child, edge] : edges) {
      text += " " + child + (edge.is_static ? " -static-> " : " -> ") + edge.parent + ";";
    }
    return text;
  }

  // target_T_source, or nothing when the frames are not connected or a loop is climbed before
  // they meet. As in tf, the source climbs first and stops at the target if it reaches it, and
  // a frame in itself is the identity.
  std::optional<Answer> lookup(const std::string& target, const std::string& source) const {
    if (target == source) return Answer{Eigen::Isometry3d::Identity(), false};
    const auto up_from_source = climb(source, target);
    if (!up_from_source) return std::nullopt;
    const Step& top = up_from_source->back();
    if (top.frame == target) return Answer{top.frame_T_start, top.any_dynamic};
    const auto up_from_target = climb(target, target);
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

  std::optional<std::vector<Step>> climb(const std::string& start, const std::string& stop) const {
    std::vector<Step> steps{{start, Eigen::Isometry3d::Identity(), false}};
    for (;;) {
      if (steps.size() > 1 && steps.back().frame == stop) return steps;
      const auto edge = edges.find(steps.back().frame);
      if (edge == edges.end()) return steps;
      if (steps.size() > edges.size()) return std::nullopt;
      const Step& below = steps.back();
      steps.push_back({edge->second.parent, edge->second.parent_T_child * below.frame_T_start,
                       below.any_dynamic || !edge->second.is_static});
    }
  }
};

class TreeChanges : public ::testing::Test {
 protected:
  static constexpr double kOlder = 1.0;
  static constexpr double kNewer = 2.0;
  static constexpr double kBetween = 1.375;

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

  void setEdge(const std::string& parent, const std::string& child, bool is_static) {
    const Eigen::Isometry3d value = randomPose();
    const Transform transform(value.translation(), Eigen::Quaterniond(value.linear()));
    if (is_static) {
      lcmtf_test::putStatic(buffer, parent, child, transform);
    } else {
      lcmtf_test::put(buffer, parent, child, at(kOlder), transform);
      lcmtf_test::put(buffer, parent, child, at(kNewer), transform);
    }
    model.edges[child] = ModelEdge{parent, value, is_static};
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
        const std::optional<Answer> expected = model.lookup(target, source);
        const std::string what =
            after + ": " + source + " in " + target + ", in the tree" + model.describe();
        EXPECT_EQ(buffer.canTransform(target, source, at(kBetween)), expected.has_value()) << what;
        if (!expected) {
          EXPECT_THROW(buffer.lookupTransform(target, source, at(kBetween)), TransformException)
              << what;
          EXPECT_THROW(buffer.lookupTransform(target, source, kLatestTime), TransformException)
              << what;
          continue;
        }
        EXPECT_TRUE(near(buffer.lookupTransform(target, source, at(kBetween)).transform,
                         expected->value, kTolerance))
            << what;
        const TransformStamped latest = buffer.lookupTransform(target, source, kLatestTime);
        EXPECT_TRUE(near(latest.transform, expected->value, kTolerance)) << what;
        EXPECT_EQ(latest.stamp, expected->any_dynamic ? at(kNewer) : kLatestTime) << what;
      }
    }
    expectTimeTravelMatchesTheModel(after);
  }

  // Every ordered pair through a third of the frames as the fixed frame (another third after
  // each change), the two halves at different times.
  void expectTimeTravelMatchesTheModel(const std::string& after) {
    ++time_travel_checks;
    for (const std::string& target : names) {
      for (const std::string& source : names) {
        for (std::size_t f = time_travel_checks % 3; f < names.size(); f += 3) {
          const std::string& fixed = names[f];
          if (!buffer.frameExists(target) || !buffer.frameExists(source) ||
              !buffer.frameExists(fixed)) {
            continue;
          }
          const std::optional<Answer> fixed_T_source = model.lookup(fixed, source);
          const std::optional<Answer> target_T_fixed = model.lookup(target, fixed);
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
  for (std::size_t i = 0; i < edges.size(); ++i) {
    setEdge(edges[i].first, edges[i].second, i % 3 == 0);
    if (i % 4 == 3 || i + 1 == edges.size()) {
      expectLookupsMatchTheModel("after edge " + std::to_string(i));
    }
    if (HasFailure()) break;
  }
}

TEST_F(TreeChanges, RandomChangesKeepEveryLookupRight) {
  std::uniform_int_distribution<std::size_t> pick(0, names.size() - 1);
  std::uniform_int_distribution<int> change(0, 19);
  for (int round = 0; round < 400; ++round) {
    const int kind = change(random);
    const std::string parent = names[pick(random)];
    const std::string child = names[pick(random)];
    std::string after = "round " + std::to_string(round) + ": ";
    if (kind == 0) {
      clear();
      after += "clear";
    } else if (kind == 1) {
      buffer.resolveFrame(child);
      after += "resolved " + child;
    } else if (parent != child) {
      const bool is_static = kind % 2 == 0;
      setEdge(parent, child, is_static);
      after += parent + " -> " + child + (is_static ? " static" : " dynamic");
    }
    expectLookupsMatchTheModel(after);
    if (HasFailure()) break;
  }
}

}  // namespace
}  // namespace lcmtf
