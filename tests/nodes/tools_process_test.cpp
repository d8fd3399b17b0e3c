// The tools as a user runs them: real processes talking over udpm (ttl=0, a port of each
// test's own), publishers started by the test, outputs read from the tools' stdout.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/buffer.hpp"
#include "lcmtf/channels.hpp"
#include "lcmtf/resend_request_t.hpp"
#include "lcmtf/transform_listener.hpp"
#include "support/child_process.hpp"
#include "support/test_lcm.hpp"

namespace lcmtf {
namespace {

using namespace std::chrono_literals;
using lcmtf_test::ChildProcess;
using testing::HasSubstr;

std::string testUrl() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return lcmtf_test::privateUdpmUrl(std::string(info->test_suite_name()) + "." + info->name());
}

ListenerOptions listenerOn(const std::string& url) {
  ListenerOptions options;
  options.lcm_url = url;
  return options;
}

// A process publishing parent -> child on TF at `rate_hz` for `duration`, signed `authority`.
std::unique_ptr<ChildProcess> publisher(
    const std::string& url, const std::string& authority, double rate_hz, const std::string& parent,
    const std::string& child, std::vector<std::string> pose = {"0", "0", "0", "0", "0", "0", "1"},
    std::chrono::milliseconds duration = 20s) {
  std::vector<std::string> arguments{
      url, authority, std::to_string(rate_hz), std::to_string(duration.count()), parent, child};
  arguments.insert(arguments.end(), pose.begin(), pose.end());
  return std::make_unique<ChildProcess>(TF_PUBLISHER_PEER_PATH, arguments);
}

// A static publisher signed 'mounts' with base -> camera a metre up; `resend_period` "0"
// answers requests only.
std::unique_ptr<ChildProcess> cameraMount(const std::string& url,
                                          const std::string& resend_period = "1") {
  return std::make_unique<ChildProcess>(
      LCMTF_STATIC_PUBLISHER_PATH,
      std::vector<std::string>{"--lcm-url", url, "--period", resend_period, "--authority", "mounts",
                               "0", "0", "1", "0", "0", "0", "base", "camera"});
}

// The numbers inside the brackets after `label` on its line of the output.
std::vector<double> numbersAfter(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  if (at == std::string::npos) return {};
  const std::size_t open = text.find('[', at);
  const std::size_t close = text.find(']', open);
  std::string inside = text.substr(open + 1, close - open - 1);
  for (char& c : inside) c = c == ',' ? ' ' : c;
  std::istringstream numbers(inside);
  std::vector<double> values;
  for (double value; numbers >> value;) values.push_back(value);
  return values;
}

// The row of the monitor's frames table for child under parent: its cells, split on spaces.
std::vector<std::string> frameRow(const std::string& report, const std::string& child,
                                  const std::string& parent) {
  std::istringstream lines(report.substr(0, report.find("Authorities:")));
  for (std::string line; std::getline(lines, line);) {
    std::istringstream cells(line);
    std::vector<std::string> row;
    for (std::string cell; cells >> cell;) row.push_back(cell);
    if (row.size() >= 2 && row[0] == child && row[1] == parent) return row;
  }
  return {};
}

TEST(StaticPublisherProcess, ListenerSeesEveryTransformOfAFile) {
  const std::string url = testUrl();
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("static-file");
  const std::string file = (directory / "mounts.yaml").string();
  std::ofstream(file) << "transforms:\n"
                         "  - {frame_id: base_link, child_frame_id: camera, x: 0.2, z: 0.5, "
                         "yaw: 1.5707963267948966}\n"
                         "  - {frame_id: camera, child_frame_id: optical, qx: 0.5, qy: -0.5, "
                         "qz: 0.5, qw: -0.5}\n";
  // --period 0: the listener, started afterwards, can only get them by asking.
  ChildProcess tool(LCMTF_STATIC_PUBLISHER_PATH,
                    {"--lcm-url", url, "--file", file, "--period", "0"});
  ASSERT_TRUE(tool.waitForStdout("optical", 5s)) << tool.stderrText();

  Buffer buffer;
  TransformListener listener(buffer, listenerOn(url));
  std::string why;
  ASSERT_TRUE(buffer.canTransform("base_link", "optical", kLatestTime, 5s, &why)) << why;
  const Transform base_T_camera =
      buffer.lookupTransform("base_link", "camera", kLatestTime).transform;
  EXPECT_TRUE(base_T_camera.translation.isApprox(Eigen::Vector3d(0.2, 0.0, 0.5), 1e-15));
  EXPECT_LT(base_T_camera.rotation.angularDistance(
                Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()))),
            1e-12);
  const Transform camera_T_optical =
      buffer.lookupTransform("camera", "optical", kLatestTime).transform;
  EXPECT_LT(camera_T_optical.rotation.angularDistance(Eigen::Quaterniond(-0.5, 0.5, -0.5, 0.5)),
            1e-12);
  std::string parent;
  ASSERT_TRUE(buffer.getParent("optical", kLatestTime, parent));
  EXPECT_EQ(parent, "camera");
  std::filesystem::remove_all(directory);
}

TEST(StaticPublisherProcess, ResendsPeriodicallyAndStopsCleanlyOnCtrlC) {
  const std::string url = testUrl();
  ChildProcess tool(LCMTF_STATIC_PUBLISHER_PATH,
                    {"--lcm-url", url, "--period", "0.1", "--authority", "mounts", "1", "2", "3",
                     "0.3", "0.2", "0.1", "base", "lidar"});
  ASSERT_TRUE(tool.waitForStdout("base -> lidar", 5s)) << tool.stderrText();
  ListenerOptions options = listenerOn(url);
  options.static_request_channel = "NOBODY_LISTENS";  // only the resends can reach this one
  Buffer buffer;
  TransformListener listener(buffer, options);
  std::string why;
  ASSERT_TRUE(buffer.canTransform("base", "lidar", kLatestTime, 5s, &why)) << why;
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("authority: 'mounts'"));
  const Transform base_T_lidar = buffer.lookupTransform("base", "lidar", kLatestTime).transform;
  EXPECT_EQ(base_T_lidar.translation, Eigen::Vector3d(1.0, 2.0, 3.0));
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()));
  EXPECT_LT(base_T_lidar.rotation.angularDistance(expected), 1e-12);

  tool.interrupt();
  EXPECT_EQ(tool.waitForExit(5s), std::optional<int>(0)) << tool.stderrText();
  EXPECT_THAT(tool.stdoutText(), HasSubstr("Stopped after answering"));
}

TEST(EchoProcess, PrintsTheNumbersOfAKnownTransformWithItsStamp) {
  const std::string url = testUrl();
  ChildProcess statics(LCMTF_STATIC_PUBLISHER_PATH,
                       {"--lcm-url", url, "0", "0", "1", "0", "0", "0", "odom", "base"});
  // odom -> base is static; map -> odom turns a quarter about z and moves (1, 2, 0).
  auto moving = publisher(url, "localizer", 20, "map", "odom",
                          {"1", "2", "0", "0", "0", "0.7071067811865476", "0.7071067811865476"});
  ChildProcess echo(LCMTF_ECHO_PATH, {"--lcm-url", url, "--once", "--precision", "6", "--timeout",
                                      "10", "map", "base"});
  ASSERT_EQ(echo.waitForExit(15s), std::optional<int>(0)) << echo.stderrText();
  const std::string out = echo.stdoutText();
  EXPECT_THAT(out, HasSubstr("'base' in 'map'"));
  EXPECT_THAT(numbersAfter(out, "translation (m)"), testing::ElementsAre(1.0, 2.0, 1.0));
  EXPECT_THAT(numbersAfter(out, "quaternion xyzw"),
              testing::ElementsAre(0.0, 0.0, 0.707107, 0.707107));
  EXPECT_THAT(numbersAfter(out, "roll pitch yaw"), testing::ElementsAre(0.0, 0.0, 1.570796));
  EXPECT_THAT(out, HasSubstr("[0.000000, 0.000000, 90.000000] deg"));
  EXPECT_THAT(out,
              HasSubstr("matrix             [ 0.000000, -1.000000,  0.000000,  1.000000]\n"
                        "                     [ 1.000000,  0.000000,  0.000000,  2.000000]\n"
                        "                     [ 0.000000,  0.000000,  1.000000,  1.000000]\n"
                        "                     [ 0.000000,  0.000000,  0.000000,  1.000000]\n"));
  std::smatch stamp;
  ASSERT_TRUE(
      std::regex_search(out, stamp, std::regex("At ([0-9]+\\.[0-9]{6}) \\(age (-?[0-9.]+) s\\)")))
      << out;
  const double stamp_seconds = std::stod(stamp[1]);
  EXPECT_NEAR(stamp_seconds, toSeconds(now()), 15.0);
  EXPECT_LT(std::stod(stamp[2]), 1.0);
}

TEST(EchoProcess, SaysWhatIsMissingUntilTheFramesArrive) {
  const std::string url = testUrl();
  ChildProcess echo(LCMTF_ECHO_PATH, {"--lcm-url", url, "--rate", "20", "map", "base"});
  ASSERT_TRUE(
      echo.waitForStderr("Waiting: no transforms received yet on TF or TF_STATIC at " + url, 5s))
      << echo.stderrText();
  auto odom = publisher(url, "odometry", 50, "odom", "base");
  ASSERT_TRUE(
      echo.waitForStderr("Waiting: frame 'map' is unknown; frames heard so far: base, odom", 5s))
      << echo.stderrText();
  auto map = publisher(url, "localizer", 50, "map", "odom");
  ASSERT_TRUE(echo.waitForStdout("'base' in 'map'", 5s)) << echo.stderrText();
  EXPECT_FALSE(echo.waitForExit(0ms)) << "echo without --once keeps printing";
  echo.interrupt();
  EXPECT_EQ(echo.waitForExit(5s), std::optional<int>(0));
}

TEST(EchoProcess, GivesUpAtTheTimeoutNamingWhatIsMissing) {
  const std::string url = testUrl();
  auto odom = publisher(url, "odometry", 50, "odom", "base");
  ChildProcess echo(LCMTF_ECHO_PATH,
                    {"--lcm-url", url, "--once", "--timeout", "1", "odom", "camera"});
  EXPECT_EQ(echo.waitForExit(10s), std::optional<int>(1));
  EXPECT_THAT(echo.stderrText(), HasSubstr("lcmtf-echo: gave up after 1.000000 s: frame 'camera' "
                                           "is unknown; frames heard so far: base, odom"));
  EXPECT_EQ(echo.stdoutText(), "");
}

TEST(EchoProcess, LooksUpAFixedInstantOrAWhileAgo) {
  const std::string url = testUrl();
  // In the past once the data around it has come, and late enough that a publisher slow to
  // start on a loaded machine still has data from before it.
  const TimePoint instant = now() + 2s;
  auto map = publisher(url, "localizer", 50, "map", "base");
  ChildProcess fixed(LCMTF_ECHO_PATH, {"--lcm-url", url, "--once", "--timeout", "10", "--time",
                                       toString(instant), "map", "base"});
  ChildProcess ago(LCMTF_ECHO_PATH, {"--lcm-url", url, "--once", "--timeout", "10", "--time",
                                     "-0.25", "map", "base"});
  ASSERT_EQ(fixed.waitForExit(15s), std::optional<int>(0)) << fixed.stderrText();
  EXPECT_THAT(fixed.stdoutText(), HasSubstr("At " + toString(instant) + " (age "));
  ASSERT_EQ(ago.waitForExit(15s), std::optional<int>(0)) << ago.stderrText();
  std::smatch age;
  const std::string out = ago.stdoutText();
  ASSERT_TRUE(std::regex_search(out, age, std::regex("\\(age ([0-9.]+) s\\)"))) << out;
  EXPECT_GE(std::stod(age[1]), 0.25);
  EXPECT_LT(std::stod(age[1]), 2.0);
}

TEST(MonitorProcess, RatesAreWithinTenPercentAndAConflictIsShown) {
  const std::string url = testUrl();
  auto fast = publisher(url, "odometry", 50, "odom", "base");
  auto slow = publisher(url, "rogue", 10, "map", "base");
  auto statics = cameraMount(url);
  ASSERT_TRUE(statics->waitForStdout("Publishing", 5s));
  ChildProcess monitor(LCMTF_MONITOR_PATH, {"--lcm-url", url, "--duration", "2"});
  ASSERT_EQ(monitor.waitForExit(15s), std::optional<int>(0)) << monitor.stderrText();
  const std::string report = monitor.stdoutText();

  const std::vector<std::string> odom_row = frameRow(report, "base", "odom");
  ASSERT_EQ(odom_row.size(), 7u) << report;
  EXPECT_EQ(odom_row[2], "odometry");
  EXPECT_NEAR(std::stod(odom_row[3]), 50.0, 5.0) << report;
  EXPECT_GE(std::stod(odom_row[4]), 0.0);
  EXPECT_LT(std::stod(odom_row[4]), 100.0);
  const std::vector<std::string> map_row = frameRow(report, "base", "map");
  ASSERT_EQ(map_row.size(), 7u) << report;
  EXPECT_NEAR(std::stod(map_row[3]), 10.0, 1.0) << report;
  const std::vector<std::string> camera_row = frameRow(report, "camera", "base");
  ASSERT_EQ(camera_row.size(), 7u) << report;
  EXPECT_EQ(camera_row[2], "mounts");
  EXPECT_EQ(camera_row[4], "static");

  EXPECT_THAT(report,
              testing::ContainsRegex(
                  "Conflicts \\(a frame sent by more than one authority\\):\n"
                  "  'base' from 'odometry' \\(parent 'odom', dynamic, [0-9]+ transforms\\); "
                  "'rogue' \\(parent 'map', dynamic, [0-9]+ transforms\\)"))
      << report;
  EXPECT_THAT(report, testing::ContainsRegex("\n  odometry +[0-9]+ +(4[5-9]|5[0-5])\\.[0-9]{2} "));
}

TEST(MonitorProcess, ShowsTheChainAndItsNetDelay) {
  const std::string url = testUrl();
  auto odom = publisher(url, "odometry", 50, "odom", "base");
  ChildProcess statics(LCMTF_STATIC_PUBLISHER_PATH,
                       {"--lcm-url", url, "0", "0", "1", "0", "0", "0", "base", "camera"});
  ASSERT_TRUE(statics.waitForStdout("Publishing", 5s));
  ChildProcess monitor(LCMTF_MONITOR_PATH, {"--lcm-url", url, "--duration", "1", "odom", "camera"});
  ASSERT_EQ(monitor.waitForExit(15s), std::optional<int>(0)) << monitor.stderrText();
  const std::string report = monitor.stdoutText();
  EXPECT_THAT(report, HasSubstr("Chain from 'odom' to 'camera': odom -> base -> camera\n"));
  std::smatch delay;
  ASSERT_TRUE(std::regex_search(report, delay,
                                std::regex("net delay: average (-?[0-9.]+) ms, max (-?[0-9.]+) ms "
                                           "over ([0-9]+) updates")))
      << report;
  EXPECT_GE(std::stod(delay[1]), 0.0);
  EXPECT_LE(std::stod(delay[1]), std::stod(delay[2]));
  EXPECT_LT(std::stod(delay[2]), 500.0);
  EXPECT_GT(std::stoi(delay[3]), 20);
  EXPECT_THAT(report, HasSubstr("Frames (* on the chain):"));
  EXPECT_THAT(report, HasSubstr("base *"));
}

TEST(MonitorProcess, StaticsSentOnlyInAnswerToItsRequestAreInTheReport) {
  const std::string url = testUrl();
  auto statics = cameraMount(url, "0");
  ASSERT_TRUE(statics->waitForStdout("Publishing", 5s));
  for (const bool with_chain : {false, true}) {
    std::vector<std::string> arguments{"--lcm-url", url, "--duration", "0.2"};
    if (with_chain) arguments.insert(arguments.end(), {"base", "camera"});
    ChildProcess monitor(LCMTF_MONITOR_PATH, arguments);
    ASSERT_EQ(monitor.waitForExit(15s), std::optional<int>(0)) << monitor.stderrText();
    EXPECT_THAT(monitor.stdoutText(),
                testing::ContainsRegex("\n  camera( \\*)? +base +mounts +- +static "));
  }
}

TEST(MonitorProcess, ContinuousModeReportsEachWindowUntilStopped) {
  const std::string url = testUrl();
  auto odom = publisher(url, "odometry", 50, "odom", "base");
  ChildProcess monitor(LCMTF_MONITOR_PATH, {"--lcm-url", url, "--continuous", "--duration", "0.4"});
  ASSERT_TRUE(monitor.waitForStdout("----\n", 10s, 3)) << monitor.stderrText();
  monitor.interrupt();
  EXPECT_EQ(monitor.waitForExit(5s), std::optional<int>(0)) << monitor.stderrText();
  const std::string out = monitor.stdoutText();
  const std::string last_full_report = out.substr(out.rfind("Heard", out.rfind("----")));
  const std::vector<std::string> row = frameRow(last_full_report, "base", "odom");
  ASSERT_EQ(row.size(), 7u) << out;
  EXPECT_NEAR(std::stod(row[3]), 50.0, 10.0) << out;
  std::smatch window;
  ASSERT_TRUE(std::regex_search(last_full_report, window, std::regex("in the ([0-9.]+) s up to")))
      << last_full_report;
  EXPECT_NEAR(std::stod(window[1]), 0.4, 0.1) << last_full_report;
}

// Watches for a request for static transforms from a program whose name starts `program`: a
// tool asks once it has subscribed to everything, so what is sent after reaches it. Made before
// the program starts, so that its request cannot come before anyone listens.
class StaticRequestWatch {
 public:
  StaticRequestWatch(lcm::LCM& lcm, std::string program) : lcm_(lcm), program_(std::move(program)) {
    subscription_ = lcm_.subscribe(kTfStaticRequestChannel, &StaticRequestWatch::onRequest, this);
  }
  ~StaticRequestWatch() { lcm_.unsubscribe(subscription_); }

  bool waitFor(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!found_ && std::chrono::steady_clock::now() < deadline) lcm_.handleTimeout(50);
    return found_;
  }

 private:
  void onRequest(const lcm::ReceiveBuffer*, const std::string&, const resend_request_t* request) {
    found_ = found_ || request->requester.rfind(program_, 0) == 0;
  }

  lcm::LCM& lcm_;
  std::string program_;
  lcm::Subscription* subscription_ = nullptr;
  bool found_ = false;
};

TEST(MonitorProcess, HostileInputIsCountedAndDescribedWhileGoodTrafficIsReported) {
  const std::string url = testUrl();
  auto odom = publisher(url, "odometry", 50, "odom", "base");
  ChildProcess echo(LCMTF_ECHO_PATH, {"--lcm-url", url, "--rate", "20", "odom", "base"});
  ASSERT_TRUE(echo.waitForStdout("'base' in 'odom'", 5s)) << echo.stderrText();
  lcm::LCM lcm(url);
  // The hostile messages go out once the monitor listens, well inside its window: its request
  // may be seen a second or more after it started on a slow (sanitizer) build, and a window of
  // 1.5 s then closed before the last of them.
  StaticRequestWatch monitor_asks(lcm, "lcmtf-monitor");
  ChildProcess monitor(LCMTF_MONITOR_PATH, {"--lcm-url", url, "--duration", "3"});
  ASSERT_TRUE(monitor_asks.waitFor(5s)) << monitor.stderrText();

  const std::uint8_t garbage[] = {0xde, 0xad, 0xbe, 0xef, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  tf_message_t nan_batch{};
  nan_batch.authority = "broken-driver";
  nan_batch.transforms.push_back({});
  nan_batch.transforms[0].utime = toUtime(now());
  nan_batch.transforms[0].parent_frame = "odom";
  nan_batch.transforms[0].child_frame = "wheel";
  nan_batch.transforms[0].translation.x = std::numeric_limits<double>::quiet_NaN();
  nan_batch.transforms[0].rotation.w = 1.0;
  nan_batch.num_transforms = 1;
  for (int i = 0; i < 5; ++i) {
    lcm.publish("TF", garbage, sizeof garbage);
    lcm.publish("TF", &nan_batch);
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_EQ(monitor.waitForExit(15s), std::optional<int>(0)) << monitor.stderrText();
  const std::string report = monitor.stdoutText();
  EXPECT_THAT(report,
              HasSubstr("Problems since start (5 malformed messages, 5 invalid transforms"));
  EXPECT_THAT(report,
              HasSubstr("from 'broken-driver': NaN or infinite value in 'odom' -> 'wheel'"));
  EXPECT_EQ(frameRow(report, "base", "odom").size(), 7u) << report;
  EXPECT_TRUE(frameRow(report, "wheel", "odom").empty()) << report;

  EXPECT_TRUE(echo.waitForStderr("lcmtf-echo: ignored a malformed message on TF", 5s))
      << echo.stderrText();
  EXPECT_FALSE(echo.waitForExit(0ms)) << "echo keeps running";
  const std::size_t printed = echo.stdoutText().size();
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  while (echo.stdoutText().size() == printed && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_GT(echo.stdoutText().size(), printed) << "echo goes on printing poses";
}

TEST(ViewFramesProcess, StaticsSentOnlyInAnswerToItsRequestAreDrawn) {
  const std::string url = testUrl();
  auto statics = cameraMount(url, "0");
  ASSERT_TRUE(statics->waitForStdout("Publishing", 5s));
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("view-statics");
  const std::string output = (directory / "tree").string();
  ChildProcess view(LCMTF_VIEW_FRAMES_PATH, {"--lcm-url", url, "--wait", "0.2", "-o", output});
  ASSERT_EQ(view.waitForExit(30s), std::optional<int>(0)) << view.stderrText();
  EXPECT_THAT(lcmtf_test::readWholeFile(output + ".gv"),
              HasSubstr("\"base\" -> \"camera\" [label=\"static\\nbroadcaster: mounts\\n"));
  std::filesystem::remove_all(directory);
}

TEST(ViewFramesProcess, WritesTheTreeAsDotAndDrawsItWhenGraphvizIsThere) {
  const std::string url = testUrl();
  auto odom = publisher(url, "odometry", 50, "odom", "base");
  auto statics = cameraMount(url);
  ASSERT_TRUE(statics->waitForStdout("Publishing", 5s));
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("view-frames");
  const std::string output = (directory / "tree").string();
  ChildProcess view(LCMTF_VIEW_FRAMES_PATH, {"--lcm-url", url, "--wait", "1.5", "-o", output});
  ASSERT_EQ(view.waitForExit(30s), std::optional<int>(0)) << view.stderrText();

  const std::string dot = lcmtf_test::readWholeFile(output + ".gv");
  EXPECT_THAT(dot, testing::ContainsRegex("\"odom\" -> \"base\" \\[label=\"broadcaster: odometry"
                                          "\\\\naverage rate: (4[5-9]|5[0-5])\\.[0-9]{2} Hz"));
  EXPECT_THAT(dot, HasSubstr("\"base\" -> \"camera\" [label=\"static\\nbroadcaster: mounts\\n"));
  EXPECT_THAT(dot, HasSubstr("style=dashed"));
  const std::string out = view.stdoutText();
  EXPECT_THAT(out, HasSubstr("Heard 2 edges (1 static) from 2 broadcasters, 0 conflicts."));
  EXPECT_THAT(out, HasSubstr("Wrote " + output + ".gv\n"));
  if (std::filesystem::exists("/usr/bin/dot")) {
    EXPECT_THAT(out, HasSubstr("Wrote " + output + ".pdf\n"));
    EXPECT_THAT(out, HasSubstr("Wrote " + output + ".svg\n"));
    EXPECT_EQ(lcmtf_test::readWholeFile(output + ".pdf").substr(0, 5), "%PDF-");
    EXPECT_THAT(lcmtf_test::readWholeFile(output + ".svg"), HasSubstr("odometry"));
  }
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace lcmtf
