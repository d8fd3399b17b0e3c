// takeSnapshot and readForest: the frames a page draws, in its fixed frame, live or paused.
#include "lcmtf_viewer/scene_snapshot.hpp"

#include <gtest/gtest.h>

#include "support/buffer_core_helpers.hpp"

namespace lcmtf::viewer {
namespace {

using lcmtf_test::at;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;

const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();
constexpr auto kStale = std::chrono::seconds(1);

// odom -> base moves along x at 1 m/s from t=1 to t=2; base -> camera is static at z=1;
// a second tree map2 -> beacon is not connected to odom.
class SceneSnapshotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int i = 0; i <= 10; ++i) {
      put(buffer_, "odom", "base", at(1 + 0.1 * i), pose({0.1 * i, 0, 0}, 0, kZ), false, "driver");
    }
    putStatic(buffer_, "base", "camera", pose({0, 0, 1}, 0, kZ), "calib");
    putStatic(buffer_, "map2", "beacon", pose({5, 0, 0}, 0, kZ), "other");
  }
  FrameForest forest(double now_s = 2.0) const { return readForest(buffer_, at(now_s)); }

  BufferCore buffer_;
};

TEST_F(SceneSnapshotTest, ForestKnowsParentsRootsAndTheDynamicHistory) {
  const FrameForest trees = forest();
  EXPECT_EQ(trees.edges.size(), 3u);
  EXPECT_EQ(trees.parent_of.at("camera"), "base");
  EXPECT_EQ(trees.roots, (std::vector<std::string>{"map2", "odom"}));
  EXPECT_EQ(trees.trees.at("odom"), (std::vector<std::string>{"odom", "base", "camera"}));
  EXPECT_EQ(trees.trees.at("map2"), (std::vector<std::string>{"map2", "beacon"}));
  EXPECT_EQ(trees.oldest, at(1));
  EXPECT_EQ(trees.newest, at(2));
  EXPECT_EQ(rootOf(trees, "camera"), "odom");
  EXPECT_EQ(rootOf(trees, "odom"), "odom");
  EXPECT_EQ(rootOf(trees, "unknown"), "unknown");
}

TEST_F(SceneSnapshotTest, LiveSceneDrawsTheFixedFramesTreeAtTheNewestStamps) {
  const SceneSnapshot scene = takeSnapshot(buffer_, forest(), "odom", std::nullopt, kStale);
  EXPECT_TRUE(scene.live);
  EXPECT_EQ(scene.time, at(2));
  ASSERT_EQ(scene.poses.size(), 3u);
  EXPECT_EQ(scene.poses.at("odom"), (FramePose{0, 0, 0, 0, 0, 0, 1}));
  EXPECT_NEAR(scene.poses.at("base")[0], 1.0, 1e-12);
  EXPECT_NEAR(scene.poses.at("camera")[0], 1.0, 1e-12);
  EXPECT_NEAR(scene.poses.at("camera")[2], 1.0, 1e-12);
  ASSERT_EQ(scene.unconnected.size(), 1u);
  EXPECT_EQ(scene.unconnected[0].root, "map2");
  EXPECT_EQ(scene.unconnected[0].frames, (std::vector<std::string>{"map2", "beacon"}));
  EXPECT_TRUE(scene.stale.empty());
}

TEST_F(SceneSnapshotTest, PausedSceneInterpolatesAtTheStampAsked) {
  const SceneSnapshot scene = takeSnapshot(buffer_, forest(), "odom", at(1.25), kStale);
  EXPECT_FALSE(scene.live);
  EXPECT_EQ(scene.time, at(1.25));
  EXPECT_NEAR(scene.poses.at("base")[0], 0.25, 1e-12);
  EXPECT_NEAR(scene.poses.at("camera")[0], 0.25, 1e-12);
}

TEST_F(SceneSnapshotTest, AnotherFixedFrameDrawsTheSameTreeFromThere) {
  const SceneSnapshot scene = takeSnapshot(buffer_, forest(), "camera", at(1.5), kStale);
  EXPECT_EQ(scene.poses.at("camera"), (FramePose{0, 0, 0, 0, 0, 0, 1}));
  EXPECT_NEAR(scene.poses.at("odom")[0], -0.5, 1e-12);
  EXPECT_NEAR(scene.poses.at("odom")[2], -1.0, 1e-12);
}

TEST_F(SceneSnapshotTest, FramesWithNoDataAtThePausedStampAreLeftOut) {
  const SceneSnapshot scene = takeSnapshot(buffer_, forest(), "odom", at(0.5), kStale);
  EXPECT_EQ(scene.poses.count("odom"), 1u);
  EXPECT_EQ(scene.poses.count("base"), 0u);
  EXPECT_EQ(scene.poses.count("camera"), 0u);
}

TEST_F(SceneSnapshotTest, AnUnknownFixedFrameLeavesEveryTreeUnconnected) {
  const SceneSnapshot scene = takeSnapshot(buffer_, forest(), "nowhere", std::nullopt, kStale);
  EXPECT_TRUE(scene.poses.empty());
  EXPECT_EQ(scene.unconnected.size(), 2u);
}

TEST_F(SceneSnapshotTest, DynamicFramesWithoutNewStampsAreStaleStaticOnesNever) {
  const SceneSnapshot scene = takeSnapshot(buffer_, forest(3.5), "odom", std::nullopt, kStale);
  EXPECT_EQ(scene.stale, (std::vector<std::string>{"base"}));
}

TEST_F(SceneSnapshotTest, AutomaticFixedFramePrefersTheGivenFrameElseTheLargestTreesRoot) {
  EXPECT_EQ(automaticFixedFrame(forest(), "base"), "base");
  EXPECT_EQ(automaticFixedFrame(forest(), "not_here"), "odom");
  EXPECT_EQ(automaticFixedFrame(forest(), ""), "odom");
  EXPECT_EQ(automaticFixedFrame(readForest(BufferCore(), at(0)), "base"), "");
}

}  // namespace
}  // namespace lcmtf::viewer
