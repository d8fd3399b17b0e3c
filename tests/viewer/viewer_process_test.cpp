// lcmtf-viewer as a real process over udpm (ttl=0) beside the real URDF publisher: a WebSocket
// client sees the robot, the tree and the scene, and its sliders move the robot.
#include <gtest/gtest.h>
#include <unistd.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <fstream>
#include <regex>

#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>

#include "lcmtf/joint_state_t.hpp"
#include "support/child_process.hpp"
#include "support/test_lcm.hpp"

namespace {

using namespace std::chrono_literals;
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using lcmtf_test::ChildProcess;
using nlohmann::json;
using tcp = asio::ip::tcp;

class Page {
 public:
  explicit Page(int port) {
    socket_.next_layer().connect(
        tcp::endpoint(asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)));
    socket_.handshake("127.0.0.1", "/ws");
    socket_.text(true);
  }
  // The next message; a scene is acknowledged and applied to `drawn`, as the page does.
  json read() {
    beast::flat_buffer buffer;
    socket_.read(buffer);
    json message = json::parse(beast::buffers_to_string(buffer.data()));
    if (message.at("type") == "scene") {
      if (message.at("full").get<bool>()) drawn.clear();
      last_scene_fixed_frame = message.at("fixed_frame").get<std::string>();
      for (const auto& [frame, pose] : message.at("poses").items()) drawn[frame] = pose;
      for (const json& frame : message.at("removed")) drawn.erase(frame.get<std::string>());
      say({{"type", "ack"}, {"seq", message.at("seq")}});
    }
    return message;
  }
  // Reads until a message of `type` passing `accept` comes.
  json readUntil(const std::string& type, const std::function<bool(const json&)>& accept,
                 std::chrono::seconds patience = 10s) {
    const auto give_up = std::chrono::steady_clock::now() + patience;
    while (std::chrono::steady_clock::now() < give_up) {
      const json message = read();
      if (message.at("type") == type && accept(message)) return message;
    }
    ADD_FAILURE() << "no " << type << " message as wanted came";
    return nullptr;
  }
  // Reads until what was drawn passes `accept` (perhaps already).
  bool waitForDrawn(const std::function<bool()>& accept, std::chrono::seconds patience = 10s) {
    const auto give_up = std::chrono::steady_clock::now() + patience;
    while (!accept()) {
      if (std::chrono::steady_clock::now() > give_up) return false;
      read();
    }
    return true;
  }
  void say(const json& message) { socket_.write(asio::buffer(message.dump())); }

  std::map<std::string, json> drawn;  ///< every frame's pose as the scenes so far left it
  std::string last_scene_fixed_frame;

 private:
  asio::io_context io_;
  websocket::stream<tcp::socket> socket_{io_};
};

class ViewerProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    web_root_ = std::filesystem::temp_directory_path() /
                ("lcmtf_viewer_process_" + std::to_string(::getpid()));
    std::filesystem::create_directories(web_root_);
    std::ofstream(web_root_ / "index.html") << "<!doctype html><title>test page</title>";
    url_ =
        lcmtf_test::privateUdpmUrl(::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { std::filesystem::remove_all(web_root_); }

  std::unique_ptr<ChildProcess> startViewer() {
    auto viewer = std::make_unique<ChildProcess>(
        LCMTF_VIEWER_PATH, std::vector<std::string>{"--port", "0", "--lcm-url", url_, "--web-root",
                                                    web_root_.string()});
    EXPECT_TRUE(viewer->waitForStdout("in a browser", 10s)) << viewer->stderrText();
    std::smatch port;
    const std::string text = viewer->stdoutText();
    EXPECT_TRUE(std::regex_search(text, port, std::regex("http://127\\.0\\.0\\.1:([0-9]+)/")));
    port_ = port.empty() ? 0 : std::stoi(port[1]);
    return viewer;
  }

  std::filesystem::path web_root_;
  std::string url_;
  int port_ = 0;
};

TEST_F(ViewerProcess, APageSeesTheRobotItsTreeAndItsScene) {
  auto viewer = startViewer();
  ChildProcess publisher(URDF_PUBLISHER_PATH, {EXAMPLE_URDF, "--lcm-url", url_});
  Page page(port_);
  EXPECT_EQ(page.read().at("type"), "hello");
  const json robot =
      page.readUntil("robot", [](const json& m) { return !m.at("robot").is_null(); });
  EXPECT_EQ(robot.at("robot").at("name"), "mobile_manipulator");
  EXPECT_EQ(robot.at("robot").at("links").size(), 26u);
  // The joints have no states yet: only the fixed joints' statics are there.
  const json tree =
      page.readUntil("tree", [](const json& m) { return m.at("frames").size() >= 10; });
  EXPECT_EQ(
      tree.at("frames")[0].at("authority").get<std::string>().rfind("lcmtf-urdf-publisher@", 0),
      0u);
  // Without joint states the statics make the largest tree, whose root is drawn in.
  ASSERT_TRUE(page.waitForDrawn([&] { return page.drawn.count("laser_link") > 0; }));
  EXPECT_EQ(page.last_scene_fixed_frame, "base_footprint");

  // The robot's own page-side joint sliders drive it: the base slides 1.2 m along x.
  lcm::LCM listen(url_);
  struct Heard {
    std::vector<lcmtf::joint_state_t> states;
    void on(const lcm::ReceiveBuffer*, const std::string&, const lcmtf::joint_state_t* state) {
      states.push_back(*state);
    }
  } heard;
  listen.subscribe("JOINT_STATES", &Heard::on, &heard);
  page.say({{"type", "view"}, {"fixed_frame", "odom"}, {"time", nullptr}});
  page.say({{"type", "joints"}, {"enabled", true}, {"positions", {{"base_x_joint", 1.2}}}});
  page.readUntil("joints", [](const json& m) { return m.at("publishing").get<bool>(); });
  for (int i = 0; i < 20 && heard.states.size() < 2; ++i) listen.handleTimeout(100);
  ASSERT_GE(heard.states.size(), 2u);
  EXPECT_EQ(heard.states[0].name, std::vector<std::string>{"base_x_joint"});
  EXPECT_EQ(heard.states[0].position, std::vector<double>{1.2});
  EXPECT_NE(heard.states[0].authority.find("/page-1"), std::string::npos);
  EXPECT_TRUE(page.waitForDrawn([&] {
    return page.last_scene_fixed_frame == "odom" && page.drawn.count("base_x_link") &&
           std::abs(page.drawn.at("base_x_link")[0].get<double>() - 1.2) < 1e-9;
  }));

  viewer->interrupt();
  EXPECT_EQ(viewer->waitForExit(10s), std::optional<int>(0)) << viewer->stderrText();
  EXPECT_NE(viewer->stdoutText().find("to 1 pages"), std::string::npos) << viewer->stdoutText();
}

TEST_F(ViewerProcess, ARobotDescriptionThatArrivesLaterIsSentToOpenPages) {
  auto viewer = startViewer();
  Page page(port_);
  page.read();  // hello
  EXPECT_TRUE(page.read().at("robot").is_null());
  ChildProcess publisher(URDF_PUBLISHER_PATH, {EXAMPLE_URDF, "--lcm-url", url_});
  const json robot =
      page.readUntil("robot", [](const json& m) { return !m.at("robot").is_null(); });
  EXPECT_EQ(robot.at("robot").at("root_link"), "odom");
  EXPECT_TRUE(viewer->waitForStderr("robot 'mobile_manipulator' from ROBOT_DESCRIPTION", 5s));
}

TEST_F(ViewerProcess, ABrokenUrdfFileExitsTwoNamingIt) {
  const std::filesystem::path broken = web_root_ / "broken.urdf";
  std::ofstream(broken) << "<robot name='x'><link name='a'>";
  ChildProcess viewer(LCMTF_VIEWER_PATH, {"--port", "0", "--lcm-url", url_, "--web-root",
                                          web_root_.string(), "--urdf", broken.string()});
  EXPECT_EQ(viewer.waitForExit(10s), std::optional<int>(2));
  EXPECT_NE(viewer.stderrText().find(broken.string()), std::string::npos) << viewer.stderrText();
}

TEST_F(ViewerProcess, ControlCharactersOfARefusedRobotReachTheTerminalEscaped) {
  const std::filesystem::path refused = web_root_ / "zero_axis.urdf";
  std::ofstream(refused) << "<robot name='x'><link name='a'/><link name='b'/>"
                            "<joint name='j&#x1b;[2J' type='continuous'><parent link='a'/>"
                            "<child link='b'/><axis xyz='0 0 0'/></joint></robot>";
  ChildProcess viewer(LCMTF_VIEWER_PATH, {"--port", "0", "--lcm-url", url_, "--web-root",
                                          web_root_.string(), "--urdf", refused.string()});
  EXPECT_EQ(viewer.waitForExit(10s), std::optional<int>(2));
  EXPECT_NE(viewer.stderrText().find("joint 'j\\x1b[2J' has a zero axis"), std::string::npos)
      << viewer.stderrText();
  EXPECT_EQ(viewer.stderrText().find('\x1b'), std::string::npos);
}

TEST_F(ViewerProcess, APortInUseIsSaidPlainly) {
  auto first = startViewer();
  ChildProcess second(LCMTF_VIEWER_PATH, {"--port", std::to_string(port_), "--lcm-url", url_,
                                          "--web-root", web_root_.string()});
  EXPECT_EQ(second.waitForExit(10s), std::optional<int>(1));
  EXPECT_NE(second.stderrText().find("cannot listen on 127.0.0.1:" + std::to_string(port_)),
            std::string::npos)
      << second.stderrText();
}

}  // namespace
