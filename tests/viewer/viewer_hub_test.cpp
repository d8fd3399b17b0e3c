// ViewerHub with recording page links: what pages are sent, what they may ask, what is refused.
#include "lcmtf_viewer/viewer_hub.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/buffer_core_helpers.hpp"

namespace lcmtf::viewer {
namespace {

using lcmtf_test::pose;
using lcmtf_test::put;
using nlohmann::json;
using ::testing::HasSubstr;

class RecordingLink : public PageLink {
 public:
  void send(std::shared_ptr<const std::string> text) override {
    sent.push_back(json::parse(*text));
  }
  void close(std::uint16_t code, const std::string& reason) override {
    close_code = code;
    close_reason = reason;
  }
  std::vector<json> ofType(const std::string& type) const {
    std::vector<json> found;
    for (const json& message : sent) {
      if (message.at("type") == type) found.push_back(message);
    }
    return found;
  }
  std::vector<json> sent;
  int close_code = 0;
  std::string close_reason;
};

const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

class ViewerHubTest : public ::testing::Test {
 protected:
  ViewerHubTest()
      : hub_(buffer_, pageFiles(), settings(),
             [this](const joint_state_t& state) { published_.push_back(state); }) {}

  static ServedFiles pageFiles() {
    ServedFiles files;
    files.add("/", "/srv/index.html");
    return files;
  }
  static HubSettings settings() {
    HubSettings settings;
    settings.version = "9.9";
    settings.joint_states_channel = "JOINTS";
    settings.authority = "viewer@test";
    return settings;
  }
  void SetUp() override {
    const TimePoint t = now();
    for (int i = 0; i < 5; ++i) {
      put(buffer_, "world", "base", t - std::chrono::milliseconds(40 - 10 * i),
          pose({0.1 * i, 0, 0}, 0, kZ));
    }
    put(buffer_, "base", "link1", t, pose({0, 0, 1}, 0, kZ), true);
  }
  std::shared_ptr<RecordingLink> open() {
    auto link = std::make_shared<RecordingLink>();
    hub_.pageOpened(link);
    return link;
  }
  void say(RecordingLink& link, const json& message) {
    hub_.pageMessage(link, message.dump(), true);
  }
  static std::shared_ptr<const RobotView> robot() {
    const std::string urdf = R"(<robot name="bot"><link name="base"/><link name="link1"/>
      <link name="link2"/><joint name="j1" type="revolute"><parent link="base"/>
      <child link="link1"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>
      </joint><joint name="j2" type="revolute"><parent link="link1"/><child link="link2"/>
      <mimic joint="j1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>)";
    return std::make_shared<const RobotView>(
        makeRobotView(urdf::parseRobotModel(urdf, "test"), {}));
  }

  BufferCore buffer_;
  std::vector<joint_state_t> published_;
  ViewerHub hub_;
};

TEST_F(ViewerHubTest, ANewPageIsGreetedWithHelloRobotJointsAndTree) {
  const auto page = open();
  ASSERT_EQ(page->sent.size(), 4u);
  EXPECT_EQ(page->sent[0].at("type"), "hello");
  EXPECT_EQ(page->sent[0].at("version"), "9.9");
  EXPECT_EQ(page->sent[0].at("fixed_frame"), "world");
  EXPECT_EQ(page->sent[0].at("joint_states_channel"), "JOINTS");
  EXPECT_EQ(page->sent[1], json::parse(R"({"type":"robot","robot":null})"));
  EXPECT_EQ(page->sent[2].at("publishing"), false);
  EXPECT_EQ(page->sent[3].at("type"), "tree");
  EXPECT_EQ(page->sent[3].at("frames").size(), 2u);
  EXPECT_EQ(hub_.openPages(), 1u);
}

TEST_F(ViewerHubTest, ScenesFlowOnlyAsFastAsThePageAcknowledgesThem) {
  const auto page = open();
  hub_.sendScenes();
  hub_.sendScenes();
  auto scenes = page->ofType("scene");
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_EQ(scenes[0].at("fixed_frame"), "world");
  EXPECT_EQ(scenes[0].at("poses").size(), 3u);
  say(*page, {{"type", "ack"}, {"seq", scenes[0].at("seq")}});
  put(buffer_, "world", "base", now(), pose({2, 0, 0}, 0, kZ));
  hub_.sendScenes();
  scenes = page->ofType("scene");
  ASSERT_EQ(scenes.size(), 2u);
  EXPECT_EQ(scenes[1].at("poses").size(), 2u);  // base and link1 moved; world did not
  EXPECT_NEAR(scenes[1].at("poses").at("link1")[0].get<double>(), 2.0, 1e-12);
}

TEST_F(ViewerHubTest, AViewPausedInTheHistoryIsDrawnThereAndOneOutsideIsRefused) {
  const auto page = open();
  const TimePoint oldest = readForest(buffer_, now()).oldest;
  say(*page, {{"type", "view"}, {"fixed_frame", "link1"}, {"time", toUtime(oldest)}});
  hub_.sendScenes();
  const json scene = page->ofType("scene").back();
  EXPECT_EQ(scene.at("fixed_frame"), "link1");
  EXPECT_FALSE(scene.at("live").get<bool>());
  EXPECT_EQ(scene.at("time"), toUtime(oldest));
  EXPECT_NEAR(scene.at("poses").at("world")[2].get<double>(), -1.0, 1e-12);
  say(*page, {{"type", "view"}, {"fixed_frame", "world"}, {"time", 5}});
  EXPECT_THAT(page->ofType("error").back().at("message").get<std::string>(),
              HasSubstr("view.time: 5 is outside the history ["));
}

TEST_F(ViewerHubTest, RefusedMessagesGetErrorsAndAHundredCloseThePage) {
  const auto page = open();
  hub_.pageMessage(*page, "\x01\x02", false);
  EXPECT_EQ(page->ofType("error").back().at("message"),
            "binary messages are refused; send JSON text");
  say(*page, {{"type", "ack"}, {"seq", 99}});
  EXPECT_EQ(page->ofType("error").back().at("message"),
            "ack.seq: no scene 99 is waiting to be drawn");
  for (int i = 0; i < 97; ++i) hub_.pageMessage(*page, "{", true);
  EXPECT_EQ(page->close_code, 0);
  hub_.pageMessage(*page, "{", true);
  EXPECT_EQ(page->close_code, 1008);
  EXPECT_EQ(page->close_reason, "too many refused messages");
  EXPECT_EQ(hub_.statistics().messages_refused.load(), 100u);
}

TEST_F(ViewerHubTest, JointSlidersPublishClampedPositionsWhileOnOnly) {
  hub_.setRobot(robot());
  const auto page = open();
  say(*page, {{"type", "joints"}, {"enabled", true}, {"positions", {{"j1", 5.0}}}});
  ASSERT_EQ(published_.size(), 1u);
  EXPECT_EQ(published_[0].name, std::vector<std::string>{"j1"});
  EXPECT_EQ(published_[0].position, std::vector<double>{1.0});
  EXPECT_EQ(published_[0].authority, "viewer@test/page-1");
  EXPECT_EQ(published_[0].sequence, 1);
  EXPECT_EQ(page->ofType("joints").back(),
            json::parse(R"({"type":"joints","publishing":true,"positions":{"j1":1.0}})"));
  hub_.publishJoints();
  EXPECT_EQ(published_.size(), 2u);
  EXPECT_EQ(published_[1].sequence, 2);
  say(*page, {{"type", "joints"}, {"enabled", false}});
  hub_.publishJoints();
  EXPECT_EQ(published_.size(), 2u);
}

TEST_F(ViewerHubTest, SlidersMoveOnlyTheRobotsFreeJoints) {
  const auto page = open();
  say(*page, {{"type", "joints"}, {"enabled", true}, {"positions", {{"j1", 0.5}}}});
  EXPECT_EQ(page->ofType("error").back().at("message"), "joints.positions: no robot is loaded");
  hub_.setRobot(robot());
  say(*page, {{"type", "joints"}, {"enabled", true}, {"positions", {{"j2", 0.5}}}});
  EXPECT_EQ(page->ofType("error").back().at("message"),
            "joints.positions: 'j2' is not a joint the sliders move (movable, following no "
            "other) of 'bot'");
  EXPECT_TRUE(published_.empty());
}

TEST_F(ViewerHubTest, ANewRobotIsSentToEveryPageAndSwitchesSlidersOff) {
  hub_.setRobot(robot());
  const auto page = open();
  say(*page, {{"type", "joints"}, {"enabled", true}, {"positions", {{"j1", 0.5}}}});
  hub_.setRobot(robot());
  EXPECT_EQ(page->ofType("robot").back().at("robot").at("name"), "bot");
  EXPECT_EQ(page->ofType("joints").back().at("publishing"), false);
  const std::size_t published = published_.size();
  hub_.publishJoints();
  EXPECT_EQ(published_.size(), published);
}

TEST_F(ViewerHubTest, ServesPageFilesAndTheRobotsMeshesOnly) {
  EXPECT_NE(hub_.findFile("/"), nullptr);
  EXPECT_EQ(hub_.findFile("/mesh/0/x.stl"), nullptr);
  auto view = std::make_shared<RobotView>();
  view->robot = json::parse(R"({"name":"m","joints":[]})");
  view->meshes = {"/data/parts/x.stl"};
  hub_.setRobot(view);
  ASSERT_NE(hub_.findFile("/mesh/0/x.stl"), nullptr);
  EXPECT_EQ(hub_.findFile("/mesh/0/x.stl")->path, "/data/parts/x.stl");
  hub_.setRobot(nullptr);
  EXPECT_EQ(hub_.findFile("/mesh/0/x.stl"), nullptr);
}

TEST_F(ViewerHubTest, TreeGoesToEveryPageAndClosedPagesAreForgotten) {
  const auto a = open();
  const auto b = open();
  hub_.sendTree();
  EXPECT_EQ(a->ofType("tree").size(), 2u);
  EXPECT_EQ(b->ofType("tree").size(), 2u);
  hub_.pageClosed(*a);
  EXPECT_EQ(hub_.openPages(), 1u);
  hub_.sendTree();
  EXPECT_EQ(a->ofType("tree").size(), 2u);
  EXPECT_EQ(b->ofType("tree").size(), 3u);
}

}  // namespace
}  // namespace lcmtf::viewer
