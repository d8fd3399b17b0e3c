// The real programs as processes over udpm (ttl=0, a port of each test's own): a listener in
// this process looks up what lcmtf-joint-publisher and lcmtf-urdf-publisher produce, late
// joiners, a robot taken from the description channel, bad input, signals and exit codes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "joint_state_helpers.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf/wire_decode.hpp"
#include "program_process.hpp"
#include "support/buffer_core_helpers.hpp"
#include "support/test_lcm.hpp"
#include "urdf_reference.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::positionsOf;
using namespace std::chrono_literals;
using lcmtf_test::near;
using lcmtf_test::ProgramProcess;
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

Eigen::Isometry3d expected(const ReferenceRobot& robot, const std::string& target,
                           const std::string& source, const std::map<std::string, double>& q) {
  return robot.rootTLink(target, q).inverse() * robot.rootTLink(source, q);
}

TEST(UrdfPublisherProcess, ListenerLooksUpTheGripperAsTheSweepingJointStatesPlaceIt) {
  const std::string url = testUrl();
  Tap<joint_state_t> joint_states(url, kJointStatesChannel);
  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));
  ProgramProcess publisher(URDF_PUBLISHER_PROGRAM, {"--lcm-url", url, EXAMPLE_URDF});
  ASSERT_TRUE(publisher.waitForOutput("transforms to TF", kStartup)) << publisher.errors();
  ProgramProcess joints(JOINT_PUBLISHER_PROGRAM, {"--lcm-url", url, "--sweep", "--sweep-period",
                                                  "2", "--rate", "100", EXAMPLE_URDF});
  ASSERT_TRUE(joint_states.waitFor(20, kStartup)) << joints.errors();

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
  EXPECT_EQ(publisher.errors(), "");
}

TEST(UrdfPublisherProcess, LateJoinerGetsTheFixedJointsAndTheDescription) {
  const std::string url = testUrl();
  ProgramProcess publisher(URDF_PUBLISHER_PROGRAM,
                           {"--lcm-url", url, "--static-resend-period", "0", EXAMPLE_URDF});
  ASSERT_TRUE(publisher.waitForOutput("transforms to TF", kStartup)) << publisher.errors();
  std::this_thread::sleep_for(200ms);

  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));  // asks for the statics as it starts
  std::string why;
  EXPECT_TRUE(buffer.canTransform("gripper_base_link", "gripper_tcp", kLatestTime, 5s, &why))
      << why;
  EXPECT_TRUE(buffer.canTransform("base_link", "laser_link", kLatestTime, 5s, &why)) << why;

  Tap<robot_description_t> descriptions(url, kRobotDescriptionChannel);
  resend_request_t ask;
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
  ProgramProcess copy(URDF_PUBLISHER_PROGRAM,
                      {"--lcm-url", url, "--frame-prefix", "copy/", "--tf-channel", "TF"});
  ASSERT_TRUE(copy.waitForOutput("waiting for a robot description", kStartup)) << copy.errors();
  ProgramProcess original(URDF_PUBLISHER_PROGRAM, {"--lcm-url", url, EXAMPLE_URDF});
  ASSERT_TRUE(
      copy.waitForOutput("robot 'mobile_manipulator' from ROBOT_DESCRIPTION from "
                         "lcmtf-urdf-publisher@",
                         kStartup))
      << copy.output() << copy.errors();
  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));
  ProgramProcess joints(JOINT_PUBLISHER_PROGRAM, {"--lcm-url", url, "--rate", "50", EXAMPLE_URDF});
  std::string why;
  EXPECT_TRUE(buffer.canTransform("copy/base_link", "copy/gripper_tcp", kLatestTime, 5s, &why))
      << why;
  EXPECT_TRUE(buffer.canTransform("base_link", "gripper_tcp", kLatestTime, 5s, &why)) << why;
}

TEST(UrdfPublisherProcess, BadJointStatesOnTheNetworkAreReportedAndTheRestPublished) {
  const std::string url = testUrl();
  ProgramProcess publisher(URDF_PUBLISHER_PROGRAM, {"--lcm-url", url, EXAMPLE_URDF});
  ASSERT_TRUE(publisher.waitForOutput("transforms to TF", kStartup)) << publisher.errors();
  Tap<tf_message_t> tf(url, kTfChannel);
  lcm::LCM lcm(url);
  const std::vector<std::uint8_t> garbage(64, 0x5a);
  joint_state_t state;
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
  const std::string errors = publisher.errors();
  EXPECT_THAT(errors, HasSubstr("refused a joint state that does not decode"));
  EXPECT_THAT(errors, HasSubstr("ignored joint 'ghost'"));
  EXPECT_THAT(errors, HasSubstr("skipped joint 'wrist_1_joint' at position nan"));
  EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n'), 3) << errors;
  EXPECT_THAT(publisher.output(), HasSubstr("stopped after 6 joint states, 3 batches of 3 "
                                            "transforms; 3 malformed; 3 non-finite positions "
                                            "skipped; 3 unknown joint names"));
}

TEST(UrdfPublisherProcess, SigintAndSigtermStopBothProgramsCleanly) {
  const std::string url = testUrl();
  ProgramProcess publisher(URDF_PUBLISHER_PROGRAM, {"--lcm-url", url, EXAMPLE_URDF});
  ASSERT_TRUE(publisher.waitForOutput("transforms to TF", kStartup)) << publisher.errors();
  Tap<tf_message_t> tf(url, kTfChannel);
  ProgramProcess joints(JOINT_PUBLISHER_PROGRAM, {"--lcm-url", url, "--rate", "0.2", EXAMPLE_URDF});
  ASSERT_TRUE(tf.waitFor(1, kStartup)) << joints.errors();
  const auto start = std::chrono::steady_clock::now();
  publisher.signal(SIGINT);
  joints.signal(SIGTERM);  // mid-way through a 5 s wait between two joint states
  EXPECT_EQ(publisher.waitForExit(3s), 0);
  EXPECT_EQ(joints.waitForExit(3s), 0);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
  EXPECT_THAT(publisher.output(), HasSubstr("lcmtf-urdf-publisher: stopped after 1 joint states"));
  EXPECT_THAT(joints.output(), HasSubstr("lcmtf-joint-publisher: stopped after 1 joint states"));
}

TEST(UrdfPublisherProcess, InvalidRobotsExitNonZeroNamingTheFileAndProblem) {
  const std::string broken = testing::TempDir() + "/no_root.urdf";
  std::ofstream(broken) << "<robot name='r'><link name='a'/><link name='b'/></robot>";
  for (const char* program : {URDF_PUBLISHER_PROGRAM, JOINT_PUBLISHER_PROGRAM}) {
    ProgramProcess missing(program, {"--lcm-url", testUrl(), "/nonexistent/robot.urdf"});
    EXPECT_EQ(missing.waitForExit(kStartup), 1) << program;
    EXPECT_THAT(missing.errors(), HasSubstr("/nonexistent/robot.urdf: cannot open: No such file"));
    ProgramProcess no_root(program, {"--lcm-url", testUrl(), broken});
    EXPECT_EQ(no_root.waitForExit(kStartup), 1) << program;
    EXPECT_THAT(no_root.errors(), HasSubstr(broken + ": invalid URDF: Failed to find root link: "
                                                     "Two root links found"));
    ProgramProcess bad_option(program, {"--rate-of-fire", "9", broken});
    EXPECT_EQ(bad_option.waitForExit(kStartup), 2) << program;
    EXPECT_THAT(bad_option.errors(), HasSubstr("--rate-of-fire"));
  }
  std::remove(broken.c_str());
}

}  // namespace
}  // namespace lcmtf
