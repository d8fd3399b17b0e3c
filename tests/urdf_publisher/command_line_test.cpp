// Both programs' command lines, and their run functions in-process: what they print, when
// they refuse to start and with what exit code.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <future>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "joint_state_helpers.hpp"
#include "lcmtf_urdf/joint_publisher_program.hpp"
#include "lcmtf_urdf/urdf_publisher_program.hpp"
#include "support/test_lcm.hpp"

namespace lcmtf::urdf {
namespace {

using namespace std::chrono_literals;
using lcmtf_test::jointState;
using testing::HasSubstr;
using testing::Not;
using testing::StartsWith;

TEST(UrdfPublisherCommandLine, DefaultsFollowTheProjectsChannelsAndPublishEveryState) {
  const auto parsed = parseUrdfPublisherCommandLine({"robot.urdf"});
  ASSERT_TRUE(parsed.config) << parsed.message;
  const UrdfPublisherConfig& config = *parsed.config;
  EXPECT_EQ(config.urdf_path, "robot.urdf");
  EXPECT_EQ(config.lcm_url, "");
  EXPECT_FALSE(config.check_only);
  const UrdfPublisherOptions& p = config.publisher;
  EXPECT_EQ(p.joint_states.publish_frequency, 0.0);
  EXPECT_EQ(p.joint_states.frame_prefix, "");
  EXPECT_FALSE(p.joint_states.ignore_timestamp);
  EXPECT_THAT(p.joint_states.authority, StartsWith("lcmtf-urdf-publisher@"));
  EXPECT_EQ(p.joint_states_channel, "JOINT_STATES");
  EXPECT_EQ(p.tf_channel, "TF");
  EXPECT_EQ(p.tf_static_channel, "TF_STATIC");
  EXPECT_EQ(p.tf_static_request_channel, "TF_STATIC_REQUEST");
  EXPECT_EQ(p.description_channel, "ROBOT_DESCRIPTION");
  EXPECT_EQ(p.description_request_channel, "ROBOT_DESCRIPTION_REQUEST");
  EXPECT_EQ(p.static_resend_period, std::chrono::seconds(1));
  EXPECT_TRUE(p.publish_description);
}

TEST(UrdfPublisherCommandLine, EveryOptionIsRead) {
  const auto parsed = parseUrdfPublisherCommandLine({"--lcm-url",
                                                     "memq://",
                                                     "--frame-prefix",
                                                     "r1/",
                                                     "--publish-frequency",
                                                     "30",
                                                     "--ignore-timestamp",
                                                     "--authority",
                                                     "me",
                                                     "--joint-states-channel",
                                                     "J",
                                                     "--tf-channel",
                                                     "T",
                                                     "--static-channel",
                                                     "TS",
                                                     "--request-channel",
                                                     "TSR",
                                                     "--description-channel",
                                                     "D",
                                                     "--description-request-channel",
                                                     "DR",
                                                     "--static-resend-period",
                                                     "0.25",
                                                     "--check",
                                                     "robot.urdf"});
  ASSERT_TRUE(parsed.config) << parsed.message;
  const UrdfPublisherOptions& p = parsed.config->publisher;
  EXPECT_EQ(parsed.config->lcm_url, "memq://");
  EXPECT_TRUE(parsed.config->check_only);
  EXPECT_EQ(p.joint_states.frame_prefix, "r1/");
  EXPECT_EQ(p.joint_states.publish_frequency, 30.0);
  EXPECT_TRUE(p.joint_states.ignore_timestamp);
  EXPECT_EQ(p.joint_states.authority, "me");
  EXPECT_EQ(p.joint_states_channel, "J");
  EXPECT_EQ(p.tf_channel, "T");
  EXPECT_EQ(p.tf_static_channel, "TS");
  EXPECT_EQ(p.tf_static_request_channel, "TSR");
  EXPECT_EQ(p.description_channel, "D");
  EXPECT_EQ(p.description_request_channel, "DR");
  EXPECT_EQ(p.static_resend_period, std::chrono::milliseconds(250));
}

TEST(UrdfPublisherCommandLine, TheChannelsOldNamesStillWorkUnshown) {
  const auto parsed = parseUrdfPublisherCommandLine(
      {"--tf-static-channel", "TS", "--tf-static-request-channel", "TSR", "robot.urdf"});
  ASSERT_TRUE(parsed.config) << parsed.message;
  EXPECT_EQ(parsed.config->publisher.tf_static_channel, "TS");
  EXPECT_EQ(parsed.config->publisher.tf_static_request_channel, "TSR");
  const auto help = parseUrdfPublisherCommandLine({"--help"});
  EXPECT_THAT(help.message, Not(HasSubstr("--tf-static-channel")));
  const auto joint = parseJointPublisherCommandLine({"--channel", "ARM", "robot.urdf"});
  ASSERT_TRUE(joint.config) << joint.message;
  EXPECT_EQ(joint.config->channel, "ARM");
}

TEST(UrdfPublisherCommandLine, HelpExitsZeroAndNamesEveryOption) {
  const auto parsed = parseUrdfPublisherCommandLine({"--help"});
  EXPECT_FALSE(parsed.config);
  EXPECT_EQ(parsed.exit_code, 0);
  for (const char* option : {"--lcm-url", "--frame-prefix", "--publish-frequency",
                             "--ignore-timestamp", "--check", "--description-channel"}) {
    EXPECT_THAT(parsed.message, HasSubstr(option));
  }
}

TEST(UrdfPublisherCommandLine, BadValuesExitTwoNamingTheOption) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--publish-frequency", "nan", "r.urdf"},
       "--publish-frequency: 'nan' is not a number in [0, 1e+06]"},
      {{"--publish-frequency", "-1", "r.urdf"},
       "--publish-frequency: '-1' is not a number in [0, 1e+06]"},
      {{"--publish-frequency", "fast", "r.urdf"}, "'fast' is not a number in"},
      {{"--static-resend-period", "inf", "r.urdf"}, "'inf' is not a number in [0, 3600]"},
      {{"--frobnicate", "r.urdf"}, "--frobnicate"},
      {{"a.urdf", "b.urdf"}, "b.urdf"},
      {{"--check"}, "--check needs a URDF file"},
  };
  for (const auto& [arguments, expected] : cases) {
    const auto parsed = parseUrdfPublisherCommandLine(arguments);
    EXPECT_FALSE(parsed.config) << expected;
    EXPECT_EQ(parsed.exit_code, 2) << expected;
    EXPECT_THAT(parsed.message, HasSubstr(expected));
  }
}

TEST(JointPublisherCommandLine, DefaultsAreRestAtFiftyHertzUntilStopped) {
  const auto parsed = parseJointPublisherCommandLine({"robot.urdf"});
  ASSERT_TRUE(parsed.config) << parsed.message;
  EXPECT_EQ(parsed.config->rate, 50.0);
  EXPECT_EQ(parsed.config->duration, 0.0);
  EXPECT_EQ(parsed.config->channel, "JOINT_STATES");
  EXPECT_FALSE(parsed.config->generator.sweep);
  EXPECT_EQ(parsed.config->generator.sweep_period, 8.0);
  EXPECT_TRUE(parsed.config->generator.held.empty());
  EXPECT_THAT(parsed.config->authority, StartsWith("lcmtf-joint-publisher@"));
}

TEST(JointPublisherCommandLine, PositionsAreSplitAtTheLastEqualsSign) {
  const auto parsed = parseJointPublisherCommandLine(
      {"--sweep", "--sweep-period", "3", "--rate", "200", "--duration", "1.5", "--position",
       "elbow_joint=0.5", "--position", "odd=name=-2e-3", "--joint-states-channel", "ARM",
       "r.urdf"});
  ASSERT_TRUE(parsed.config) << parsed.message;
  const JointPublisherConfig& config = *parsed.config;
  EXPECT_TRUE(config.generator.sweep);
  EXPECT_EQ(config.generator.sweep_period, 3.0);
  EXPECT_EQ(config.rate, 200.0);
  EXPECT_EQ(config.duration, 1.5);
  EXPECT_EQ(config.channel, "ARM");
  ASSERT_EQ(config.generator.held.size(), 2u);
  EXPECT_EQ(config.generator.held[0], std::make_pair(std::string("elbow_joint"), 0.5));
  EXPECT_EQ(config.generator.held[1], std::make_pair(std::string("odd=name"), -2e-3));
}

TEST(JointPublisherCommandLine, TheFileMayFollowAHeldPosition) {
  const auto parsed =
      parseJointPublisherCommandLine({"--position", "elbow_joint=0.5", "robot.urdf"});
  ASSERT_TRUE(parsed.config) << parsed.message;
  EXPECT_EQ(parsed.config->urdf_path, "robot.urdf");
  ASSERT_EQ(parsed.config->generator.held.size(), 1u);
  EXPECT_EQ(parsed.config->generator.held[0].first, "elbow_joint");
}

TEST(JointPublisherCommandLine, BadValuesExitTwoNamingTheOption) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--rate", "0", "r.urdf"}, "--rate: '0' is not a number in [0.01, 10000]"},
      {{"--rate", "inf", "r.urdf"}, "'inf' is not a number in"},
      {{"--position", "elbow", "r.urdf"}, "'elbow' is not JOINT=VALUE"},
      {{"--position", "=1", "r.urdf"}, "'=1' is not JOINT=VALUE"},
      {{"--position", "elbow=nan", "r.urdf"}, "'elbow=nan' is not JOINT=VALUE with a finite VALUE"},
      {{"--sweep-period", "0", "r.urdf"}, "--sweep-period: '0' is not a number in"},
      {{"--duration", "-1", "r.urdf"}, "--duration: '-1' is not a number in"},
  };
  for (const auto& [arguments, expected] : cases) {
    const auto parsed = parseJointPublisherCommandLine(arguments);
    EXPECT_FALSE(parsed.config) << expected;
    EXPECT_EQ(parsed.exit_code, 2) << expected;
    EXPECT_THAT(parsed.message, HasSubstr(expected));
  }
}

struct ProgramRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

ProgramRun runUrdfPublisherWith(const std::vector<std::string>& arguments,
                                std::chrono::milliseconds stop_after = 0ms) {
  const auto parsed = parseUrdfPublisherCommandLine(arguments);
  EXPECT_TRUE(parsed.config) << parsed.message;
  std::atomic<bool> stop{stop_after == 0ms};
  std::ostringstream out;
  std::ostringstream err;
  auto running = std::async(std::launch::async,
                            [&] { return runUrdfPublisher(*parsed.config, stop, out, err); });
  std::this_thread::sleep_for(stop_after);
  stop = true;
  ProgramRun run;
  run.exit_code = running.get();
  run.out = out.str();
  run.err = err.str();
  return run;
}

TEST(UrdfPublisherRun, MissingFileExitsTwoNamingIt) {
  const ProgramRun run = runUrdfPublisherWith({"/nonexistent/robot.urdf"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err,
            "lcmtf-urdf-publisher: /nonexistent/robot.urdf: cannot open: No such file or "
            "directory\n");
}

TEST(UrdfPublisherRun, UnusableLcmUrlExitsTwoNamingIt) {
  const ProgramRun run = runUrdfPublisherWith({"--lcm-url", "nonsense://", EXAMPLE_URDF});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "lcmtf-urdf-publisher: --lcm-url: cannot open LCM at 'nonsense://'\n");
}

TEST(UrdfPublisherRun, CheckListsTheRobotAndExitsZero) {
  const ProgramRun run = runUrdfPublisherWith({"--check", "--frame-prefix", "r1/", EXAMPLE_URDF});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.out, HasSubstr("robot 'mobile_manipulator' from " + std::string(EXAMPLE_URDF) +
                                 ": 26 links, root 'r1/odom'"));
  EXPECT_THAT(run.out, HasSubstr("revolute elbow_joint: r1/upper_arm_link -> r1/forearm_link"));
  EXPECT_EQ(run.err, "");
}

// Names of a URDF, which may come from the network, with the terminal's escape and bell.
TEST(UrdfPublisherRun, ControlCharactersInNamesReachTheTerminalEscaped) {
  const std::string path = testing::TempDir() + "/control_characters.urdf";
  std::ofstream(path) << "<robot name='r&#x1b;[2J'><link name='base&#x7;'/><link name='arm'/>"
                         "<joint name='j' type='fixed'><parent link='base&#x7;'/>"
                         "<child link='arm'/></joint></robot>";
  for (const ProgramRun& run : {runUrdfPublisherWith({"--check", path}),
                                runUrdfPublisherWith({"--lcm-url", "memq://", path}, 50ms)}) {
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_THAT(run.out,
                HasSubstr("robot 'r\\x1b[2J' from " + path + ": 2 links, root 'base\\x07'"));
    EXPECT_EQ(run.out.find_first_of("\x1b\x07"), std::string::npos) << run.out;
  }
  std::remove(path.c_str());
}

TEST(UrdfPublisherRun, RunsUntilStoppedThenSaysWhatItHandled) {
  const ProgramRun run = runUrdfPublisherWith({"--lcm-url", "memq://", EXAMPLE_URDF}, 150ms);
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.out, HasSubstr("joint states from JOINT_STATES, transforms to TF and TF_STATIC, "
                                 "via 'memq://'"));
  EXPECT_THAT(run.out, HasSubstr("lcmtf-urdf-publisher: stopped after 0 joint states, 0 batches "
                                 "of 0 transforms"));
}

TEST(UrdfPublisherRun, WithoutAFileItWaitsForADescriptionUntilStopped) {
  const ProgramRun run = runUrdfPublisherWith({"--lcm-url", "memq://"}, 150ms);
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.out, HasSubstr("no URDF file given: waiting for a robot description on "
                                 "ROBOT_DESCRIPTION (asking on ROBOT_DESCRIPTION_REQUEST)"));
}

ProgramRun runJointPublisherWith(const std::vector<std::string>& arguments) {
  const auto parsed = parseJointPublisherCommandLine(arguments);
  EXPECT_TRUE(parsed.config) << parsed.message;
  const std::atomic<bool> stop{false};
  std::ostringstream out;
  std::ostringstream err;
  ProgramRun run;
  run.exit_code = runJointPublisher(*parsed.config, stop, out, err);
  run.out = out.str();
  run.err = err.str();
  return run;
}

TEST(JointPublisherRun, PublishesAtItsRateForItsDuration) {
  const ProgramRun run = runJointPublisherWith(
      {"--lcm-url", "memq://", "--rate", "100", "--duration", "0.3", "--sweep", EXAMPLE_URDF});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("14 joints of robot 'mobile_manipulator' sweeping, 100 joint "
                                 "states per second on JOINT_STATES via 'memq://'"));
  const auto at = run.out.find("stopped after ");
  ASSERT_NE(at, std::string::npos) << run.out;
  const int published = std::stoi(run.out.substr(at + 14));
  EXPECT_GE(published, 10);  // a busy machine may publish late, never more often
  EXPECT_LE(published, 31);
}

TEST(JointPublisherRun, ADurationShorterThanThePeriodEndsOnTime) {
  const auto start = std::chrono::steady_clock::now();
  const ProgramRun run = runJointPublisherWith(
      {"--lcm-url", "memq://", "--rate", "0.2", "--duration", "0.2", EXAMPLE_URDF});
  EXPECT_LT(std::chrono::steady_clock::now() - start, 2s);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("stopped after 1 joint states"));
}

TEST(JointPublisherRun, WithoutAFileItWaitsForADescriptionNoLongerThanItsDuration) {
  const auto start = std::chrono::steady_clock::now();
  const ProgramRun run = runJointPublisherWith({"--lcm-url", "memq://", "--duration", "0.3"});
  EXPECT_LT(std::chrono::steady_clock::now() - start, 3s);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("no valid robot description heard on ROBOT_DESCRIPTION within "
                                 "0.3 s"));
}

// joint_state_publisher's source_list: what other programs publish wins over the generated.
TEST(JointPublisherRun, PositionsFromItsSourcesTakeThePlaceOfItsOwn) {
  const std::string url =
      lcmtf_test::privateUdpmUrl("JointPublisherRun.PositionsFromItsSourcesTakeThePlaceOfItsOwn");
  struct Latest {
    void onState(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
      if (state.decode(buffer->data, 0, static_cast<int>(buffer->data_size)) > 0) ++count;
    }
    double position(const std::string& joint) const {
      for (std::size_t i = 0; i < state.name.size(); ++i) {
        if (state.name[i] == joint) return state.position[i];
      }
      return std::nan("");
    }
    joint_state_t state{};
    int count = 0;
  } latest;
  lcm::LCM lcm(url);
  lcm.subscribe(kJointStatesChannel, &Latest::onState, &latest);
  const auto parsed = parseJointPublisherCommandLine({"--lcm-url", url, "--source", "ARM_STATES",
                                                      "--source", "GRIPPER_STATES", "--rate", "50",
                                                      "--duration", "1.5", EXAMPLE_URDF});
  ASSERT_TRUE(parsed.config) << parsed.message;
  const std::atomic<bool> stop{false};
  std::ostringstream out, err;
  auto running = std::async(std::launch::async,
                            [&] { return runJointPublisher(*parsed.config, stop, out, err); });
  joint_state_t arm = jointState(1, {"elbow_joint"}, {0.7});
  joint_state_t gripper = jointState(1, {"gripper_left_finger_joint", "not_a_joint"}, {0.03, 1.0});
  while (running.wait_for(0ms) != std::future_status::ready) {
    lcm.publish("ARM_STATES", &arm);
    lcm.publish("GRIPPER_STATES", &gripper);
    lcm.handleTimeout(20);
  }
  EXPECT_EQ(running.get(), 0) << err.str();
  ASSERT_GT(latest.count, 10);
  EXPECT_EQ(latest.position("elbow_joint"), 0.7);
  EXPECT_EQ(latest.position("gripper_left_finger_joint"), 0.03);
  EXPECT_EQ(latest.position("gripper_right_finger_joint"), -0.03) << "the mimic follows it";
  EXPECT_EQ(latest.position("shoulder_pan_joint"), 0.0) << "the rest as generated";
}

TEST(JointPublisherCommandLine, ASourceCannotBeTheChannelItPublishesOn) {
  const auto parsed = parseJointPublisherCommandLine({"--source", "JOINT_STATES", "r.urdf"});
  EXPECT_FALSE(parsed.config);
  EXPECT_EQ(parsed.exit_code, 2);
  EXPECT_THAT(parsed.message, HasSubstr("--source JOINT_STATES is the channel it publishes on"));
}

TEST(JointPublisherRun, ARobotWithoutMovableJointsExitsOneSayingSo) {
  const std::string path = testing::TempDir() + "/rigid.urdf";
  {
    std::ofstream(path) << "<robot name='rigid'><link name='a'/><link name='b'/><joint name='j' "
                           "type='fixed'><parent link='a'/><child link='b'/></joint></robot>";
  }
  const ProgramRun run = runJointPublisherWith({"--lcm-url", "memq://", path});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err,
            "lcmtf-joint-publisher: robot 'rigid' has no movable joint that follows no other: no "
            "joint states to publish\n");
  std::remove(path.c_str());
}

TEST(JointPublisherRun, HoldingAnUnknownJointExitsTwoNamingItAndTheJointMeant) {
  const ProgramRun run = runJointPublisherWith(
      {"--lcm-url", "memq://", "--position", "knee=0.1", "--duration", "5", EXAMPLE_URDF});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err,
            "lcmtf-joint-publisher: --position: robot 'mobile_manipulator' has no movable joint "
            "'knee'\n");
  const ProgramRun typo = runJointPublisherWith(
      {"--lcm-url", "memq://", "--position", "elbw_joint=0.1", "--duration", "5", EXAMPLE_URDF});
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_THAT(typo.err, HasSubstr("has no movable joint 'elbw_joint' (did you mean "
                                  "'elbow_joint'?)"));
}

TEST(JointPublisherRun, InvalidUrdfExitsTwoNamingTheFileAndProblem) {
  const std::string path = testing::TempDir() + "/zero_axis.urdf";
  {
    std::ofstream(path) << "<robot name='r'><link name='a'/><link name='b'/><joint name='j' "
                           "type='continuous'><parent link='a'/><child link='b'/>"
                           "<axis xyz='0 0 0'/></joint></robot>";
  }
  const ProgramRun run = runJointPublisherWith({"--lcm-url", "memq://", path});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "lcmtf-joint-publisher: " + path +
                         ": joint 'j' has a zero axis (0 0 0): it cannot say which way the "
                         "joint moves\n");
  std::remove(path.c_str());
}

}  // namespace
}  // namespace lcmtf::urdf
