// PageSession: the first scene is whole, then only what changed, one scene in flight at a time.
#include "lcmtf_viewer/page_session.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace lcmtf::viewer {
namespace {

using nlohmann::json;

const TimePoint kT0 = fromUtime(1'700'000'000'000'000);

SceneSnapshot sceneWith(std::map<std::string, FramePose> poses, TimePoint time = kT0) {
  SceneSnapshot scene;
  scene.fixed_frame = "odom";
  scene.time = time;
  scene.poses = std::move(poses);
  return scene;
}

json next(PageSession& session, const SceneSnapshot& scene) {
  const auto text = session.sceneMessage(scene, kT0 - std::chrono::seconds(10), kT0);
  if (!text) return nullptr;
  const json message = json::parse(*text);
  EXPECT_TRUE(session.acknowledge(message.at("seq").get<std::int64_t>()));
  return message;
}

constexpr FramePose kHere = {0, 0, 0, 0, 0, 0, 1};
constexpr FramePose kThere = {1, 2, 3, 0, 0, 0, 1};

TEST(PageSession, FirstSceneIsWholeThenOnlyChangedPosesAndRemovedFrames) {
  PageSession session;
  const json first = next(session, sceneWith({{"odom", kHere}, {"base", kHere}, {"arm", kHere}}));
  EXPECT_TRUE(first.at("full").get<bool>());
  EXPECT_EQ(first.at("seq"), 1);
  EXPECT_EQ(first.at("poses").size(), 3u);
  EXPECT_EQ(first.at("time"), toUtime(kT0));
  EXPECT_EQ(first.at("history").at("oldest"), toUtime(kT0) - 10'000'000);

  const json second = next(session, sceneWith({{"odom", kHere}, {"base", kThere}}));
  EXPECT_FALSE(second.at("full").get<bool>());
  EXPECT_EQ(second.at("poses"), json({{"base", {1, 2, 3, 0, 0, 0, 1}}}));
  EXPECT_EQ(second.at("removed"), json({"arm"}));
}

TEST(PageSession, NothingIsSentWhenNothingChanged) {
  PageSession session;
  next(session, sceneWith({{"odom", kHere}}));
  EXPECT_TRUE(next(session, sceneWith({{"odom", kHere}})).is_null());
  FramePose moved_a_little = kHere;
  moved_a_little[0] = 1e-9;  // below what can be seen
  EXPECT_TRUE(next(session, sceneWith({{"odom", moved_a_little}})).is_null());
  EXPECT_FALSE(
      next(session, sceneWith({{"odom", kHere}}, kT0 + std::chrono::milliseconds(1))).is_null());
}

TEST(PageSession, WaitsForTheAckBeforeTheNextScene) {
  PageSession session;
  ASSERT_TRUE(session.readyForScene());
  const auto text = session.sceneMessage(sceneWith({{"odom", kHere}}), kT0, kT0);
  ASSERT_TRUE(text);
  EXPECT_FALSE(session.readyForScene());
  EXPECT_FALSE(session.acknowledge(7));
  EXPECT_FALSE(session.readyForScene());
  EXPECT_TRUE(session.acknowledge(1));
  EXPECT_TRUE(session.readyForScene());
  EXPECT_FALSE(session.acknowledge(1));  // once only
}

TEST(PageSession, AViewMakesTheNextSceneWholeAgain) {
  PageSession session;
  next(session, sceneWith({{"odom", kHere}, {"base", kHere}}));
  session.view("base", kT0 - std::chrono::seconds(2));
  EXPECT_EQ(session.chosenFixedFrame(), "base");
  EXPECT_EQ(session.pausedAt(), kT0 - std::chrono::seconds(2));
  const json whole = next(session, sceneWith({{"odom", kHere}, {"base", kHere}}));
  ASSERT_FALSE(whole.is_null());
  EXPECT_TRUE(whole.at("full").get<bool>());
  EXPECT_EQ(whole.at("poses").size(), 2u);
  EXPECT_TRUE(whole.at("removed").empty());
}

TEST(PageSession, UnconnectedTreesAndStaleFramesAreSent) {
  PageSession session;
  SceneSnapshot scene = sceneWith({{"odom", kHere}});
  scene.unconnected = {UnconnectedTree{"map2", {"map2", "x"}}};
  scene.stale = {"camera"};
  const json message = next(session, scene);
  EXPECT_EQ(message.at("unconnected"), json::parse(R"([{"root":"map2","frames":["map2","x"]}])"));
  EXPECT_EQ(message.at("stale"), json({"camera"}));
  scene.stale.clear();
  EXPECT_EQ(next(session, scene).at("stale"), json::array());
}

}  // namespace
}  // namespace lcmtf::viewer
