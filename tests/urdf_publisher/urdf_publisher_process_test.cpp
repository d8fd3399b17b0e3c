// The real programs as processes over udpm (ttl=0, a port of each test's own): a listener in
// this process looks up what lcmtf-joint-publisher and lcmtf-urdf-publisher produce, late
// joiners, a robot taken from the description channel, bad input, descriptions too large to
// parse, signals and exit codes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "joint_state_helpers.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf/wire_decode.hpp"
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

constexpr auto kStartup = 10s;  // generous: sanitizer builds start slowly

std::string testUrl() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  return lcmtf_test::privateUdpmUrl(std::string(info->test_suite_name()) + "." + info->name());
}

ListenerOptions onUrl(const std::string& url) {
  ListenerOptions options;
  options.lcm_url = url;
  return options;
}

// Every message of one type on one channel, heard on an LCM and thread of its own.
template <class Message>
class Tap {
 public:
  Tap(const std::string& url, const std::string& channel) : lcm_(url) {
    lcm_.subscribe(channel, &Tap::onMessage, this);
    thread_ = std::thread([this] {
      while (!stopping_) lcm_.handleTimeout(20);
    });
  }
  ~Tap() {
    stopping_ = true;
    thread_.join();
  }

  std::vector<Message> messages() const {
    std::lock_guard<std::mutex> guard(mutex_);
    return messages_;
  }
  bool waitFor(std::size_t count, std::chrono::milliseconds timeout) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (messages().size() < count) {
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(5ms);
    }
    return true;
  }
  lcm::LCM& lcm() { return lcm_; }

 private:
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
    Message message;
    if (!decodeMessage(buffer->data, buffer->data_size, message).ok) return;
    std::lock_guard<std::mutex> guard(mutex_);
    messages_.push_back(std::move(message));
  }

  lcm::LCM lcm_;
  mutable std::mutex mutex_;
  std::vector<Message> messages_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

// A robot 40,001 elements deep, which would overflow the XML parser's stack.
std::string tooDeepRobot() {
  std::string text = "<robot name='d'>";
  for (int level = 0; level < 40'000; ++level) text += "<x>";
  return text;
}

// 150,000 links, each joined to the one before: urdfdom would free them recursively.
void writeTooLongChain(const std::string& path) {
  std::ofstream file(path);
  file << "<robot name='chain'><link name='l0'/>";
  for (int i = 1; i < 150'000; ++i) {
    file << "<link name='l" << i << "'/><joint name='j" << i << "' type='fixed'><parent link='l"
         << i - 1 << "'/><child link='l" << i << "'/></joint>";
  }
  file << "</robot>";
}

void sendDescription(lcm::LCM& lcm, const std::string& urdf) {
  robot_description_t description{};
  description.utime = toUtime(now());
  description.authority = "sender";
  description.robot_name = "r";
  description.urdf = urdf;
  lcm.publish(kRobotDescriptionChannel, &description);
}

Eigen::Isometry3d expected(const ReferenceRobot& robot, const std::string& target,
                           const std::string& source, const std::map<std::string, double>& q) {
  return robot.rootTLink(target, q).inverse() * robot.rootTLink(source, q);
}

TEST(UrdfPublisherProcess, ListenerLooksUpTheGripperAsTheSweepingJointStatesPlaceIt) {
  const std::string url = testUrl();
  Tap<joint_state_t> joint_states(url, kJointStatesChannel);
  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));
  ChildProcess publisher(URDF_PUBLISHER_PROGRAM, {"--lcm-url", url, EXAMPLE_URDF});
  ASSERT_TRUE(publisher.waitForStdout("transforms to TF", kStartup)) << publisher.stderrText();
  ChildProcess joints(JOINT_PUBLISHER_PROGRAM, {"--lcm-url", url, "--sweep", "--sweep-period", "2",
                                                "--rate", "100", EXAMPLE_URDF});
  ASSERT_TRUE(joint_states.waitFor(20, kStartup)) << joints.stderrText();

  const ReferenceRobot reference(EXAMPLE_URDF);
  int checked = 0;
  for (const joint_state_t& state : joint_states.messages()) {
    const TimePoint stamp = fromUtime(state.utime);
    std::string why;
    if (!buffer.canTransform("base_link", "gripper_tcp", stamp, 2s, &why)) {
      // The listener may have started after the first few batches went out.
      EXPECT_LT(checked, 1) << why;
      continue;
    }
    const auto q = positionsOf(state);
    EXPECT_TRUE(near(buffer.lookupTransform("base_link", "gripper_tcp", stamp).transform,
                     expected(reference, "base_link", "gripper_tcp", q), 1e-9));
    EXPECT_TRUE(near(buffer.lookupTransform("odom", "camera_optical_frame", stamp).transform,
                     expected(reference, "odom", "camera_optical_frame", q), 1e-9));
    EXPECT_TRUE(near(
        buffer.lookupTransform("gripper_left_finger_link", "gripper_right_finger_link", stamp)
            .transform,
        expected(reference, "gripper_left_finger_link", "gripper_right_finger_link", q), 1e-9));
    ++checked;
  }
  EXPECT_GE(checked, 15);
  EXPECT_EQ(listener.statistics().rejected_transforms, 0u);
  EXPECT_EQ(publisher.stderrText(), "");
}

TEST(UrdfPublisherProcess, LateJoinerGetsTheFixedJointsAndTheDescription) {
  const std::string url = testUrl();
  ChildProcess publisher(URDF_PUBLISHER_PROGRAM,
                         {"--lcm-url", url, "--static-resend-period", "0", EXAMPLE_URDF});
  ASSERT_TRUE(publisher.waitForStdout("transforms to TF", kStartup)) << publisher.stderrText();
  std::this_thread::sleep_for(200ms);

  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));  // asks for the statics as it starts
  std::string why;
  EXPECT_TRUE(buffer.canTransform("gripper_base_link", "gripper_tcp", kLatestTime, 5s, &why))
      << why;
  EXPECT_TRUE(buffer.canTransform("base_link", "laser_link", kLatestTime, 5s, &why)) << why;

  Tap<robot_description_t> descriptions(url, kRobotDescriptionChannel);
  resend_request_t ask{};
  ask.utime = toUtime(now());
  ask.requester = "test";
  descriptions.lcm().publish(kRobotDescriptionRequestChannel, &ask);
  ASSERT_TRUE(descriptions.waitFor(1, 5s));
  std::ifstream file(EXAMPLE_URDF);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(descriptions.messages()[0].urdf, text);
  EXPECT_EQ(descriptions.messages()[0].robot_name, "mobile_manipulator");
}

TEST(UrdfPublisherProcess, PublisherWithoutAFileTakesTheRobotFromTheDescriptionChannel) {
  const std::string url = testUrl();
  ChildProcess copy(URDF_PUBLISHER_PROGRAM,
                    {"--lcm-url", url, "--frame-prefix", "copy/", "--tf-channel", "TF"});
  ASSERT_TRUE(copy.waitForStdout("waiting for a robot description", kStartup)) << copy.stderrText();
  ChildProcess original(URDF_PUBLISHER_PROGRAM, {"--lcm-url", url, EXAMPLE_URDF});
  ASSERT_TRUE(
      copy.waitForStdout("robot 'mobile_manipulator' from ROBOT_DESCRIPTION from "
                         "lcmtf-urdf-publisher@",
                         kStartup))
      << copy.stdoutText() << copy.stderrText();
  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));
  ChildProcess joints(JOINT_PUBLISHER_PROGRAM, {"--lcm-url", url, "--rate", "50", EXAMPLE_URDF});
  std::string why;
  EXPECT_TRUE(buffer.canTransform("copy/base_link", "copy/gripper_tcp", kLatestTime, 5s, &why))
      << why;
  EXPECT_TRUE(buffer.canTransform("base_link", "gripper_tcp", kLatestTime, 5s, &why)) << why;
}

TEST(UrdfPublisherProcess, BadJointStatesOnTheNetworkAreReportedAndTheRestPublished) {
  const std::string url = testUrl();
  ChildProcess publisher(URDF_PUBLISHER_PROGRAM, {"--lcm-url", url, EXAMPLE_URDF});
  ASSERT_TRUE(publisher.waitForStdout("transforms to TF", kStartup)) << publisher.stderrText();
  Tap<tf_message_t> tf(url, kTfChannel);
  lcm::LCM lcm(url);
  const std::vector<std::uint8_t> garbage(64, 0x5a);
  joint_state_t state{};
  state.utime = toUtime(now());
  state.name = {"elbow_joint", "ghost", "wrist_1_joint"};
  state.position = {0.5, 1.0, std::nan("")};
  state.num_joints = 3;
  state.num_positions = 3;
  state.num_velocities = 0;
  state.num_efforts = 0;
  for (int k = 0; k < 3; ++k) {
    lcm.publish(kJointStatesChannel, garbage.data(), static_cast<unsigned>(garbage.size()));
    lcm.publish(kJointStatesChannel, &state);
  }
  ASSERT_TRUE(tf.waitFor(3, 5s));
  for (const tf_message_t& batch : tf.messages()) {
    ASSERT_EQ(batch.transforms.size(), 1u);
    EXPECT_EQ(batch.transforms[0].child_frame, "forearm_link");
  }
  publisher.signal(SIGTERM);
  ASSERT_EQ(publisher.waitForExit(5s), 0);
  const std::string errors = publisher.stderrText();
  EXPECT_THAT(errors, HasSubstr("refused a joint state that does not decode"));
  EXPECT_THAT(errors, HasSubstr("ignored joint 'ghost'"));
  EXPECT_THAT(errors, HasSubstr("skipped joint 'wrist_1_joint' at position nan"));
  EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n'), 3) << errors;
  EXPECT_THAT(publisher.stdoutText(), HasSubstr("stopped after 6 joint states, 3 batches of 3 "
                                                "transforms; 3 malformed; 3 non-finite positions "
                                                "skipped; 3 unknown joint names"));
}

TEST(UrdfPublisherProcess, SigintAndSigtermStopBothProgramsCleanly) {
  const std::string url = testUrl();
  ChildProcess publisher(URDF_PUBLISHER_PROGRAM, {"--lcm-url", url, EXAMPLE_URDF});
  ASSERT_TRUE(publisher.waitForStdout("transforms to TF", kStartup)) << publisher.stderrText();
  Tap<tf_message_t> tf(url, kTfChannel);
  ChildProcess joints(JOINT_PUBLISHER_PROGRAM, {"--lcm-url", url, "--rate", "0.2", EXAMPLE_URDF});
  ASSERT_TRUE(tf.waitFor(1, kStartup)) << joints.stderrText();
  const auto start = std::chrono::steady_clock::now();
  publisher.signal(SIGINT);
  joints.signal(SIGTERM);  // mid-way through a 5 s wait between two joint states
  EXPECT_EQ(publisher.waitForExit(3s), 0);
  EXPECT_EQ(joints.waitForExit(3s), 0);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
  EXPECT_THAT(publisher.stdoutText(),
              HasSubstr("lcmtf-urdf-publisher: stopped after 1 joint states"));
  EXPECT_THAT(joints.stdoutText(),
              HasSubstr("lcmtf-joint-publisher: stopped after 1 joint states"));
}

// Status 2, as for any file a command line names that is wrong.
TEST(UrdfPublisherProcess, InvalidRobotsExitTwoNamingTheFileAndProblem) {
  const std::string broken = testing::TempDir() + "/no_root.urdf";
  std::ofstream(broken) << "<robot name='r'><link name='a'/><link name='b'/></robot>";
  for (const char* program : {URDF_PUBLISHER_PROGRAM, JOINT_PUBLISHER_PROGRAM}) {
    ChildProcess missing(program, {"--lcm-url", testUrl(), "/nonexistent/robot.urdf"});
    EXPECT_EQ(missing.waitForExit(kStartup), 2) << program;
    EXPECT_THAT(missing.stderrText(),
                HasSubstr("/nonexistent/robot.urdf: cannot open: No such file"));
    ChildProcess no_root(program, {"--lcm-url", testUrl(), broken});
    EXPECT_EQ(no_root.waitForExit(kStartup), 2) << program;
    EXPECT_THAT(no_root.stderrText(),
                HasSubstr(broken + ": invalid URDF: Failed to find root link: "
                                   "Two root links found"));
    ChildProcess bad_option(program, {"--rate-of-fire", "9", broken});
    EXPECT_EQ(bad_option.waitForExit(kStartup), 2) << program;
    EXPECT_THAT(bad_option.stderrText(), HasSubstr("--rate-of-fire"));
  }
  std::remove(broken.c_str());
}

TEST(UrdfPublisherProcess, CheckRefusesFilesTooDeepOrWithTooManyLinksNamingTheLimit) {
  const std::string deep = testing::TempDir() + "/too_deep.urdf";
  std::ofstream(deep) << tooDeepRobot();
  const std::string chain = testing::TempDir() + "/too_long_chain.urdf";
  writeTooLongChain(chain);
  const std::pair<std::string, std::string> refusals[] = {
      {deep, ": elements nested 40001 deep; the limit is 256"},
      {chain, ": 150000 links; the limit is 10000"}};
  for (const auto& [file, refusal] : refusals) {
    ChildProcess check(URDF_PUBLISHER_PROGRAM, {"--check", file});
    EXPECT_EQ(check.waitForExit(kStartup), 2) << file;
    EXPECT_EQ(check.stderrText(), "lcmtf-urdf-publisher: " + file + refusal + "\n");
    EXPECT_EQ(check.stdoutText(), "");
  }
  std::remove(deep.c_str());
  std::remove(chain.c_str());
}

TEST(UrdfPublisherProcess, ProgramsWaitingForADescriptionReportATooDeepOneOnceAndTakeTheNext) {
  std::ostringstream valid;
  valid << std::ifstream(EXAMPLE_URDF).rdbuf();
  for (const std::string program : {URDF_PUBLISHER_PROGRAM, JOINT_PUBLISHER_PROGRAM}) {
    const std::string url = testUrl();
    Tap<resend_request_t> requests(url, kRobotDescriptionRequestChannel);
    ChildProcess waiting(program, {"--lcm-url", url});
    ASSERT_TRUE(requests.waitFor(1, kStartup)) << waiting.stderrText();  // it listens from then on
    lcm::LCM& lcm = requests.lcm();
    for (int k = 0; k < 3; ++k) {
      sendDescription(lcm, tooDeepRobot());
      std::this_thread::sleep_for(100ms);
    }
    ASSERT_TRUE(waiting.waitForStderr("the limit is 256", kStartup)) << waiting.stderrText();
    EXPECT_EQ(waiting.waitForExit(100ms), std::nullopt) << waiting.stderrText();

    sendDescription(lcm, valid.str());
    ASSERT_TRUE(waiting.waitForStdout("robot 'mobile_manipulator'", kStartup))
        << program << waiting.stdoutText() << waiting.stderrText();
    EXPECT_THAT(waiting.stdoutText(),
                HasSubstr("refused 3 of the 4 robot descriptions heard on ROBOT_DESCRIPTION"));
    EXPECT_EQ(waiting.stderrText(),
              std::filesystem::path(program).filename().string() +
                  ": refused a robot description: ROBOT_DESCRIPTION from sender: "
                  "elements nested 40001 deep; the limit is 256\n");
  }
}

}  // namespace
}  // namespace lcmtf
