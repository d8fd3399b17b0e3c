// The demo: its report against the test's own kinematics, and scripts/demo.sh running the
// three programs and stopping every one of them, at the end of --duration and on Ctrl-C.
#include <dirent.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "demo_report.hpp"
#include "joint_state_helpers.hpp"
#include "lcmtf/message_conversions.hpp"
#include "lcmtf_urdf/joint_state_generator.hpp"
#include "lcmtf_urdf/joint_state_processor.hpp"
#include "support/buffer_core_helpers.hpp"
#include "support/child_process.hpp"
#include "support/test_lcm.hpp"
#include "urdf_reference.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::positionsOf;
using namespace std::chrono_literals;
using lcmtf_test::ChildProcess;
using lcmtf_test::near;
using lcmtf_test::ReferenceRobot;
using testing::HasSubstr;

constexpr std::int64_t kStart = 1'700'000'000'000'000;
constexpr std::int64_t kPeriod = 20'000;  // 50 Hz, as the demo's joint publisher

class DemoReportTest : public testing::Test {
 protected:
  // `seconds` of the sweeping demo robot in the buffer, as the programs would put it there.
  void sweepFor(double seconds) {
    urdf::JointStateGeneratorOptions sweeping;
    sweeping.sweep = true;
    const urdf::JointStateGenerator generator(robot_, sweeping);
    urdf::JointStateProcessor processor(robot_);
    buffer_.setTransforms(urdf::fixedJointTransforms(robot_, ""), "test", true);
    for (std::int64_t k = 0; k * kPeriod <= static_cast<std::int64_t>(seconds * 1e6); ++k) {
      const joint_state_t state = generator.stateAt(static_cast<double>(k * kPeriod) * 1e-6,
                                                    fromUtime(kStart + k * kPeriod));
      states_[state.utime] = positionsOf(state);
      for (const transform_t& t : processor.process(state)->transforms) {
        ASSERT_TRUE(buffer_.setTransform(fromMessage(t), "test"));
      }
    }
  }

  const urdf::RobotModel robot_ = urdf::loadRobotModel(EXAMPLE_URDF);
  const ReferenceRobot reference_{EXAMPLE_URDF};
  BufferCore buffer_;
  std::map<std::int64_t, std::map<std::string, double>> states_;
};

TEST_F(DemoReportTest, ReportsTheGripperAndTheObjectSeenTwoSecondsAgoFromTheLatestData) {
  sweepFor(3.0);
  const demo::DemoFrames frames;
  const Eigen::Vector3d object(0.1, -0.2, 1.5);
  std::string why;
  const auto report = demo::makeDemoReport(buffer_, frames, 2s, object, &why);
  ASSERT_TRUE(report) << why;
  const std::int64_t latest = states_.rbegin()->first;
  EXPECT_EQ(report->time, fromUtime(latest));
  EXPECT_EQ(report->seen_at, fromUtime(latest - 2'000'000));

  const auto& now_q = states_.at(latest);
  const auto& then_q = states_.at(latest - 2'000'000);
  const Eigen::Isometry3d base_T_tcp = reference_.rootTLink("base_link", now_q).inverse() *
                                       reference_.rootTLink("gripper_tcp", now_q);
  EXPECT_TRUE(near(report->base_T_end_effector, base_T_tcp, 1e-9));
  const Eigen::Vector3d in_odom = reference_.rootTLink("camera_optical_frame", then_q) * object;
  EXPECT_TRUE(report->object_in_fixed.isApprox(in_odom, 1e-9));
  const Eigen::Vector3d in_base_now = reference_.rootTLink("base_link", now_q).inverse() * in_odom;
  EXPECT_LT((report->object_in_base - in_base_now).norm(), 1e-9);
  EXPECT_GT((report->object_in_base - object).norm(), 0.01) << "the robot should have moved";
}

TEST_F(DemoReportTest, WaitsUntilTheBufferHoldsTheLookBack) {
  sweepFor(1.0);
  std::string why;
  EXPECT_FALSE(demo::makeDemoReport(buffer_, {}, 2s, Eigen::Vector3d::UnitZ(), &why));
  EXPECT_THAT(why, HasSubstr("extrapolation into the past"));
  EXPECT_FALSE(demo::makeDemoReport(BufferCore(), {}, 2s, Eigen::Vector3d::UnitZ(), &why));
  EXPECT_THAT(why, HasSubstr("odom"));
}

TEST_F(DemoReportTest, TheReportReadsAsTwoLinesNamingTheFrames) {
  sweepFor(2.5);
  const demo::DemoFrames frames;
  const auto report = demo::makeDemoReport(buffer_, frames, 2s, Eigen::Vector3d(0, 0, 1.5));
  ASSERT_TRUE(report);
  const std::string text = demo::formatDemoReport(*report, frames);
  EXPECT_THAT(text, HasSubstr("gripper_tcp in base_link: xyz ["));
  EXPECT_THAT(text, HasSubstr("\n    what the camera saw 2.0 s ago at [ 0.000  0.000  1.500] in "
                              "camera_optical_frame is now at ["));
  EXPECT_THAT(text, HasSubstr("] in odom)"));
}

// Processes still running whose command line mentions `text`.
std::vector<std::string> processesMentioning(const std::string& text) {
  std::vector<std::string> found;
  DIR* proc = opendir("/proc");
  if (!proc) return found;
  while (const dirent* entry = readdir(proc)) {
    const std::string pid = entry->d_name;
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream file("/proc/" + pid + "/cmdline");
    std::string cmdline((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    for (char& c : cmdline) c = c == '\0' ? ' ' : c;
    std::ifstream stat("/proc/" + pid + "/stat");
    std::string stat_line;
    std::getline(stat, stat_line);
    const bool zombie = stat_line.find(") Z ") != std::string::npos;
    if (!zombie && cmdline.find(text) != std::string::npos) found.push_back(pid + ": " + cmdline);
  }
  closedir(proc);
  return found;
}

std::string demoUrl() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  return lcmtf_test::privateUdpmUrl(std::string("demo.") + info->name());
}

std::unique_ptr<ChildProcess> startDemo(const std::vector<std::string>& arguments) {
  setenv("LCMTF_DEMO_BIN", DEMO_BIN_DIR, 1);
  std::vector<std::string> all{DEMO_SCRIPT};
  all.insert(all.end(), arguments.begin(), arguments.end());
  return std::make_unique<ChildProcess>("/bin/bash", all);
}

TEST(DemoScript, RunsThePublishersAndListenerForItsDurationThenStopsThemAll) {
  const std::string url = demoUrl();
  auto demo = startDemo({"--duration", "3.5", "--lcm-url", url, "--viewer-port", "0"});
  ASSERT_EQ(demo->waitForExit(20s), 0) << demo->stdoutText() << demo->stderrText();
  const std::string output = demo->stdoutText();
  EXPECT_THAT(output, HasSubstr("lcmtf-joint-publisher: 14 joints of robot 'mobile_manipulator' "
                                "sweeping"));
  EXPECT_THAT(output, HasSubstr("gripper_tcp in base_link: xyz ["));
  EXPECT_THAT(output, HasSubstr("what the camera saw 2.0 s ago"));
  EXPECT_THAT(output, HasSubstr("lcmtf-urdf-publisher: stopped after "));
  EXPECT_THAT(output, HasSubstr("lcmtf-joint-publisher: stopped after "));
  EXPECT_THAT(output, testing::ContainsRegex(
                          "lcmtf-viewer: open http://127\\.0\\.0\\.1:[0-9]+/ in a browser"));
  EXPECT_THAT(output, HasSubstr("lcmtf-viewer: served "));
  EXPECT_THAT(processesMentioning(url), testing::IsEmpty());
}

TEST(DemoScript, CtrlCStopsEveryProgramItStarted) {
  const std::string url = demoUrl();
  auto demo = startDemo({"--lcm-url", url, "--viewer-port", "0"});
  ASSERT_TRUE(demo->waitForStdout("joint states from JOINT_STATES", 10s)) << demo->stderrText();
  ASSERT_TRUE(demo->waitForStdout("waiting for transforms", 10s)) << demo->stderrText();
  EXPECT_EQ(processesMentioning(url).size(), 5u);  // the script and its four programs
  demo->signal(SIGINT);
  EXPECT_EQ(demo->waitForExit(10s), 130);
  EXPECT_THAT(demo->stdoutText(), HasSubstr("lcmtf-urdf-publisher: stopped after "));
  EXPECT_THAT(processesMentioning(url), testing::IsEmpty());
}

TEST(DemoScript, UnknownArgumentIsRefused) {
  auto demo = startDemo({"--speed", "9"});
  EXPECT_EQ(demo->waitForExit(10s), 2);
  EXPECT_THAT(demo->stderrText(), HasSubstr("demo.sh: unknown argument '--speed'"));
}

}  // namespace
}  // namespace lcmtf
