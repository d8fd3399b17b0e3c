// From joint states to transform batches: what is published, how it is stamped and named,
// the rate cap, and every kind of bad input counted and reported once.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "joint_state_helpers.hpp"
#include "lcmtf/message_conversions.hpp"
#include "lcmtf_urdf/joint_motion.hpp"
#include "lcmtf_urdf/joint_state_processor.hpp"
#include "support/buffer_core_helpers.hpp"
#include "support/sample_messages.hpp"

namespace lcmtf::urdf {
namespace {

using lcmtf_test::jointState;
using testing::ElementsAre;
using testing::HasSubstr;
using testing::UnorderedElementsAre;

constexpr std::int64_t kStamp = 1'700'000'000'000'000;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<std::string> children(const tf_message_t* batch) {
  std::vector<std::string> result;
  if (batch) {
    for (const transform_t& t : batch->transforms) result.push_back(t.child_frame);
  }
  return result;
}

const transform_t* find(const tf_message_t* batch, const std::string& child) {
  for (const transform_t& t : batch->transforms) {
    if (t.child_frame == child) return &t;
  }
  return nullptr;
}

class JointStateProcessorTest : public testing::Test {
 protected:
  JointStateOptions options() {
    JointStateOptions result;
    result.authority = "test-authority";
    result.reporter = [this](const std::string& message) { reports.push_back(message); };
    return result;
  }

  const RobotModel robot = loadRobotModel(EXAMPLE_URDF);
  std::vector<std::string> reports;
};

TEST_F(JointStateProcessorTest, PublishesTheNamedJointsStampedWithTheMessageUtime) {
  JointStateProcessor processor(robot, options());
  const TimePoint arrival = fromUtime(kStamp + 1234);
  const tf_message_t* batch = processor.process(
      jointState(kStamp, {"elbow_joint", "head_pan_joint"}, {0.5, -1.0}), arrival);
  ASSERT_NE(batch, nullptr);
  EXPECT_THAT(children(batch), ElementsAre("forearm_link", "head_pan_link"));
  EXPECT_EQ(batch->authority, "test-authority");
  EXPECT_EQ(batch->utime, kStamp + 1234);
  EXPECT_EQ(batch->num_transforms, 2);
  for (const transform_t& t : batch->transforms) EXPECT_EQ(t.utime, kStamp);
  const MovableJoint& elbow = *robot.findMovableJoint("elbow_joint");
  EXPECT_TRUE(
      fromMessage(*find(batch, "forearm_link")).transform.isApprox(parentTChild(elbow, 0.5)));
  EXPECT_EQ(find(batch, "forearm_link")->parent_frame, "upper_arm_link");
  EXPECT_EQ(processor.statistics().batches, 1u);
  EXPECT_EQ(processor.statistics().transforms, 2u);
  EXPECT_TRUE(reports.empty());
}

TEST_F(JointStateProcessorTest, EncodedJointStatesGiveTheSameBatch) {
  JointStateProcessor processor(robot, options());
  const auto bytes =
      lcmtf_test::encode(jointState(kStamp, {"wrist_2_joint", "base_x_joint"}, {0.25, 1.0}));
  const tf_message_t* batch = processor.process(bytes.data(), bytes.size());
  EXPECT_THAT(children(batch), ElementsAre("wrist_2_link", "base_x_link"));
  EXPECT_NEAR(find(batch, "base_x_link")->translation.x, 1.0, 1e-15);
}

TEST_F(JointStateProcessorTest, MimicJointIsPublishedWithItsLeader) {
  JointStateProcessor processor(robot, options());
  const tf_message_t* batch =
      processor.process(jointState(kStamp, {"gripper_left_finger_joint"}, {0.03}));
  EXPECT_THAT(children(batch),
              ElementsAre("gripper_left_finger_link", "gripper_right_finger_link"));
  EXPECT_NEAR(find(batch, "gripper_left_finger_link")->translation.y, 0.01 + 0.03, 1e-15);
  EXPECT_NEAR(find(batch, "gripper_right_finger_link")->translation.y, -0.01 - 0.03, 1e-15);
}

TEST_F(JointStateProcessorTest, EveryJointOfAMimicChainFollowsItsHead) {
  // j2 = 2 * j1 + 0.5, j3 = -1 * j2 + 0.1 = -2 * j1 - 0.4 (prismatic along x).
  const RobotModel chain = parseRobotModel(
      "<robot name='r'><link name='a'/><link name='b'/><link name='c'/><link name='d'/>"
      "<joint name='j1' type='prismatic'><parent link='a'/><child link='b'/>"
      "<limit lower='-9' upper='9' effort='1' velocity='1'/></joint>"
      "<joint name='j3' type='prismatic'><parent link='c'/><child link='d'/>"
      "<limit lower='-9' upper='9' effort='1' velocity='1'/>"
      "<mimic joint='j2' multiplier='-1' offset='0.1'/></joint>"
      "<joint name='j2' type='prismatic'><parent link='b'/><child link='c'/>"
      "<limit lower='-9' upper='9' effort='1' velocity='1'/>"
      "<mimic joint='j1' multiplier='2' offset='0.5'/></joint></robot>",
      "chain");
  JointStateProcessor processor(chain, options());
  const tf_message_t* batch = processor.process(jointState(kStamp, {"j1"}, {1.5}));
  ASSERT_THAT(children(batch), UnorderedElementsAre("b", "c", "d"));
  EXPECT_NEAR(find(batch, "b")->translation.x, 1.5, 1e-15);
  EXPECT_NEAR(find(batch, "c")->translation.x, 3.5, 1e-15);
  EXPECT_NEAR(find(batch, "d")->translation.x, -3.4, 1e-15);
}

TEST_F(JointStateProcessorTest, UnknownJointIsIgnoredAndReportedOncePerName) {
  JointStateProcessor processor(robot, options());
  for (int k = 0; k < 3; ++k) {
    const tf_message_t* batch = processor.process(
        jointState(kStamp + k, {"ghost", "elbow_joint", "phantom"}, {1.0, 0.2, 2.0}));
    EXPECT_THAT(children(batch), ElementsAre("forearm_link"));
  }
  EXPECT_EQ(processor.statistics().unknown_joints, 6u);
  ASSERT_EQ(reports.size(), 2u);
  EXPECT_EQ(reports[0],
            "ignored joint 'ghost': robot 'mobile_manipulator' has no such joint (reported once "
            "per name)");
  EXPECT_THAT(reports[1], HasSubstr("ignored joint 'phantom'"));
}

TEST_F(JointStateProcessorTest, UnknownNameIsReportedWithItsControlBytesEscaped) {
  JointStateProcessor processor(robot, options());
  processor.process(jointState(kStamp, {"evil\x1b[2J\n"}, {1.0}));
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr("ignored joint 'evil\\x1b[2J\\x0a'"));
}

TEST_F(JointStateProcessorTest, NonFinitePositionSkipsThatJointAndIsCounted) {
  JointStateProcessor processor(robot, options());
  const tf_message_t* batch = processor.process(jointState(
      kStamp, {"elbow_joint", "wrist_1_joint", "gripper_left_finger_joint", "head_tilt_joint"},
      {kNaN, 0.3, kInf, -kInf}));
  EXPECT_THAT(children(batch), ElementsAre("wrist_1_link"));
  processor.process(jointState(kStamp + 1, {"elbow_joint"}, {kNaN}));
  EXPECT_EQ(processor.statistics().non_finite_positions, 4u);
  ASSERT_EQ(reports.size(), 3u);
  EXPECT_THAT(reports[0], HasSubstr("skipped joint 'elbow_joint' at position nan"));
  EXPECT_THAT(reports[1], HasSubstr("skipped joint 'gripper_left_finger_joint' at position inf"));
}

TEST_F(JointStateProcessorTest, MimicWhosePositionOverflowsIsSkippedAndCounted) {
  // j2 = 1e300 * j1: a finite leader gives an infinite follower, which is never sent.
  const RobotModel robot_with_gain = parseRobotModel(
      "<robot name='r'><link name='a'/><link name='b'/><link name='c'/>"
      "<joint name='j1' type='continuous'><parent link='a'/><child link='b'/></joint>"
      "<joint name='j2' type='prismatic'><parent link='b'/><child link='c'/>"
      "<limit lower='-9' upper='9' effort='1' velocity='1'/>"
      "<mimic joint='j1' multiplier='1e300'/></joint></robot>",
      "gain");
  JointStateProcessor processor(robot_with_gain, options());
  const tf_message_t* batch = processor.process(jointState(kStamp, {"j1"}, {1e10}));
  ASSERT_THAT(children(batch), ElementsAre("b"));
  EXPECT_EQ(batch->num_transforms, 1);
  for (const transform_t& t : batch->transforms) {
    EXPECT_TRUE(std::isfinite(t.translation.x) && std::isfinite(t.rotation.w));
  }
  EXPECT_EQ(processor.statistics().non_finite_positions, 1u);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr("skipped joint 'j2' at position inf"));
  EXPECT_THAT(children(processor.process(jointState(kStamp + 1, {"j1"}, {1e-301}))),
              ElementsAre("b", "c"));
}

TEST_F(JointStateProcessorTest, PrismaticPositionTooLargeForItsOriginIsSkipped) {
  const RobotModel far_robot = parseRobotModel(
      "<robot name='r'><link name='a'/><link name='b'/>"
      "<joint name='slide' type='prismatic'><parent link='a'/><child link='b'/>"
      "<origin xyz='1e308 0 0'/><limit lower='-9' upper='9' effort='1' velocity='1'/>"
      "</joint></robot>",
      "far");
  JointStateProcessor processor(far_robot, options());
  EXPECT_EQ(processor.process(jointState(kStamp, {"slide"}, {1e308})), nullptr);
  EXPECT_EQ(processor.statistics().non_finite_positions, 1u);
  EXPECT_EQ(processor.statistics().batches, 0u);
  EXPECT_NE(processor.process(jointState(kStamp, {"slide"}, {-1.0})), nullptr);
}

TEST_F(JointStateProcessorTest, MessageWithAllPositionsBadPublishesNothing) {
  JointStateProcessor processor(robot, options());
  EXPECT_EQ(processor.process(jointState(kStamp, {"elbow_joint"}, {kNaN})), nullptr);
  EXPECT_EQ(processor.process(jointState(kStamp, {}, {})), nullptr);
  EXPECT_EQ(processor.statistics().received, 2u);
  EXPECT_EQ(processor.statistics().batches, 0u);
}

TEST_F(JointStateProcessorTest, NameAndPositionCountMismatchRejectsTheMessage) {
  JointStateProcessor processor(robot, options());
  EXPECT_EQ(processor.process(jointState(kStamp, {"elbow_joint", "wrist_1_joint"}, {0.1})),
            nullptr);
  EXPECT_EQ(processor.process(jointState(kStamp, {"elbow_joint"}, {0.1, 0.2})), nullptr);
  EXPECT_EQ(processor.statistics().length_mismatches, 2u);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0],
            "refused a joint state with 2 names but 1 positions (reported once; later ones are "
            "only counted)");
  EXPECT_NE(processor.process(jointState(kStamp, {"elbow_joint"}, {0.1})), nullptr);
}

TEST_F(JointStateProcessorTest, EncodedStateWithoutPositionsIsRefusedNotGivenTheLastOnes) {
  JointStateProcessor processor(robot, options());
  const auto full = lcmtf_test::encode(jointState(kStamp, {"elbow_joint"}, {0.1}));
  ASSERT_NE(processor.process(full.data(), full.size()), nullptr);
  const auto names_only = lcmtf_test::encode(jointState(kStamp + 1, {"elbow_joint"}, {}));
  EXPECT_EQ(processor.process(names_only.data(), names_only.size()), nullptr);
  EXPECT_EQ(processor.statistics().length_mismatches, 1u);
  const auto empty = lcmtf_test::encode(jointState(kStamp + 2, {}, {}));
  EXPECT_EQ(processor.process(empty.data(), empty.size()), nullptr);
  EXPECT_EQ(processor.statistics().length_mismatches, 1u) << "an empty state is not a mismatch";
}

TEST_F(JointStateProcessorTest, BytesThatDoNotDecodeAreCountedAndReportedOnce) {
  JointStateProcessor processor(robot, options());
  const std::vector<std::uint8_t> garbage{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  EXPECT_EQ(processor.process(garbage.data(), garbage.size()), nullptr);
  auto truncated = lcmtf_test::encode(jointState(kStamp, {"elbow_joint"}, {0.1}));
  truncated.resize(truncated.size() - 3);
  EXPECT_EQ(processor.process(truncated.data(), truncated.size()), nullptr);
  EXPECT_EQ(processor.process(nullptr, 0), nullptr);
  const auto other_type = lcmtf_test::encode(lcmtf_test::sampleTfMessage());
  EXPECT_EQ(processor.process(other_type.data(), other_type.size()), nullptr);
  EXPECT_EQ(processor.statistics().malformed, 4u);
  EXPECT_EQ(processor.statistics().received, 4u);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr("refused a joint state that does not decode: "));
}

TEST_F(JointStateProcessorTest, UnstampedJointStateIsRefusedWithAHint) {
  JointStateProcessor processor(robot, options());
  EXPECT_EQ(processor.process(jointState(0, {"elbow_joint"}, {0.1})), nullptr);
  EXPECT_EQ(processor.process(jointState(-5, {"elbow_joint"}, {0.1})), nullptr);
  EXPECT_EQ(processor.statistics().unstamped, 2u);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr("stamp it, or run with --ignore-timestamp"));
}

TEST_F(JointStateProcessorTest, IgnoreTimestampStampsWithTheArrivalTime) {
  JointStateOptions ignoring = options();
  ignoring.ignore_timestamp = true;
  JointStateProcessor processor(robot, ignoring);
  const TimePoint arrival = fromUtime(kStamp + 777);
  const tf_message_t* batch = processor.process(jointState(0, {"elbow_joint"}, {0.1}), arrival);
  ASSERT_NE(batch, nullptr);
  EXPECT_EQ(batch->transforms[0].utime, kStamp + 777);
}

TEST_F(JointStateProcessorTest, PositionsOfFixedJointsAreIgnoredOncePerName) {
  JointStateProcessor processor(robot, options());
  for (int k = 0; k < 2; ++k) {
    const tf_message_t* batch =
        processor.process(jointState(kStamp + k, {"camera_joint", "elbow_joint"}, {1.0, 0.1}));
    EXPECT_THAT(children(batch), ElementsAre("forearm_link"));
  }
  EXPECT_EQ(processor.statistics().ignored_joints, 2u);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr("'camera_joint': it is a fixed joint"));
}

// As in robot_state_publisher 2: the message's own value for a mimic joint wins.
TEST_F(JointStateProcessorTest, AMimicPositionGivenInTheJointStateWinsOverItsLeaders) {
  JointStateProcessor processor(robot, options());
  const tf_message_t* batch = processor.process(jointState(
      kStamp, {"gripper_left_finger_joint", "gripper_right_finger_joint"}, {0.03, -0.01}));
  ASSERT_THAT(children(batch),
              ElementsAre("gripper_left_finger_link", "gripper_right_finger_link"));
  // Its leader would put it at -0.03: the right finger's origin is 0.01 to the right.
  EXPECT_NEAR(find(batch, "gripper_right_finger_link")->translation.y, -0.01 - 0.01, 1e-15);
  EXPECT_EQ(processor.statistics().given_mimic_positions, 1u);
  EXPECT_TRUE(reports.empty());
}

TEST_F(JointStateProcessorTest, AMimicGivenWithoutItsLeaderIsPublishedAlone) {
  JointStateProcessor processor(robot, options());
  const tf_message_t* batch =
      processor.process(jointState(kStamp, {"gripper_right_finger_joint"}, {-0.02}));
  ASSERT_THAT(children(batch), ElementsAre("gripper_right_finger_link"));
  EXPECT_NEAR(batch->transforms[0].translation.y, -0.01 - 0.02, 1e-15);
}

TEST_F(JointStateProcessorTest, ANewRobotReplacesTheJointsAndTheCountsGoOn) {
  JointStateProcessor processor(robot, options());
  processor.process(jointState(kStamp, {"elbow_joint"}, {0.1}));
  processor.setRobot(parseRobotModel(
      "<robot name='r'><link name='a'/><link name='b'/>"
      "<joint name='j1' type='continuous'><parent link='a'/><child link='b'/></joint></robot>",
      "new"));
  EXPECT_THAT(children(processor.process(jointState(kStamp + 1, {"j1"}, {0.2}))), ElementsAre("b"));
  EXPECT_EQ(processor.process(jointState(kStamp + 2, {"elbow_joint"}, {0.1})), nullptr);
  EXPECT_EQ(processor.statistics().batches, 2u);
  EXPECT_EQ(processor.statistics().unknown_joints, 1u);
}

TEST_F(JointStateProcessorTest, PositionOfAFloatingJointIsIgnoredWithHowToPublishIt) {
  const RobotModel floating = parseRobotModel(
      "<robot name='r'><link name='world'/><link name='pelvis'/>"
      "<joint name='free' type='floating'><parent link='world'/><child link='pelvis'/></joint>"
      "</robot>",
      "floating");
  JointStateProcessor processor(floating, options());
  EXPECT_EQ(processor.process(jointState(kStamp, {"free"}, {1.0})), nullptr);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr("a floating joint, whose pose a joint state cannot give: "
                                    "publish its transform yourself"));
}

TEST_F(JointStateProcessorTest, RepeatedJointInOneMessageKeepsTheFirstValue) {
  JointStateProcessor processor(robot, options());
  const tf_message_t* batch =
      processor.process(jointState(kStamp, {"base_x_joint", "base_x_joint"}, {0.5, 0.9}));
  ASSERT_THAT(children(batch), ElementsAre("base_x_link"));
  EXPECT_NEAR(batch->transforms[0].translation.x, 0.5, 1e-15);
  EXPECT_EQ(processor.statistics().duplicate_joints, 1u);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr("joint 'base_x_joint' appears twice in one joint state"));
}

TEST_F(JointStateProcessorTest, RepeatedJointAfterANonFiniteValueGivesItsFiniteValue) {
  JointStateProcessor processor(robot, options());
  const tf_message_t* batch =
      processor.process(jointState(kStamp, {"base_x_joint", "base_x_joint"}, {kNaN, 0.9}));
  ASSERT_THAT(children(batch), ElementsAre("base_x_link"));
  EXPECT_NEAR(batch->transforms[0].translation.x, 0.9, 1e-15);
  EXPECT_EQ(processor.statistics().non_finite_positions, 1u);
  EXPECT_EQ(processor.statistics().duplicate_joints, 0u);
}

TEST_F(JointStateProcessorTest, NamesInAnotherOrderEachTimeStillFindTheirJoints) {
  JointStateProcessor processor(robot, options());
  const std::vector<std::vector<std::string>> orders{{"elbow_joint", "wrist_1_joint"},
                                                     {"wrist_1_joint", "elbow_joint"},
                                                     {"elbow_joint"},
                                                     {"ghost", "elbow_joint", "wrist_1_joint"},
                                                     {"wrist_1_joint", "elbow_joint"}};
  for (const auto& names : orders) {
    std::vector<double> positions;
    for (const std::string& name : names) positions.push_back(name == "elbow_joint" ? 0.5 : -0.5);
    const tf_message_t* batch = processor.process(jointState(kStamp, names, positions));
    ASSERT_NE(batch, nullptr);
    for (const transform_t& t : batch->transforms) {
      const char* joint = t.child_frame == "forearm_link" ? "elbow_joint" : "wrist_1_joint";
      EXPECT_TRUE(fromMessage(t).transform.isApprox(
          parentTChild(*robot.findMovableJoint(joint), joint[0] == 'e' ? 0.5 : -0.5)))
          << t.child_frame;
    }
  }
}

TEST_F(JointStateProcessorTest, FramePrefixIsWrittenBeforeEveryFrameName) {
  JointStateOptions prefixed = options();
  prefixed.frame_prefix = "robot1/";
  JointStateProcessor processor(robot, prefixed);
  const tf_message_t* batch =
      processor.process(jointState(kStamp, {"gripper_left_finger_joint"}, {0.01}));
  ASSERT_NE(batch, nullptr);
  for (const transform_t& t : batch->transforms) {
    EXPECT_EQ(t.parent_frame, "robot1/gripper_base_link");
    EXPECT_THAT(t.child_frame, testing::StartsWith("robot1/gripper_"));
  }
  for (const TransformStamped& t : fixedJointTransforms(robot, "robot1/")) {
    EXPECT_THAT(t.parent_frame, testing::StartsWith("robot1/"));
    EXPECT_THAT(t.child_frame, testing::StartsWith("robot1/"));
  }
}

// Feeds `count` joint states of `names`, `period_us` apart (plus `jitter_us` alternating),
// and counts the batches.
int publishedOf(JointStateProcessor& processor, const std::vector<std::string>& names,
                std::int64_t start, std::int64_t period_us, int count, std::int64_t jitter_us = 0) {
  int published = 0;
  for (int k = 0; k < count; ++k) {
    const std::int64_t stamp = start + k * period_us + (k % 2 == 0 ? jitter_us : -jitter_us);
    const std::vector<double> positions(names.size(), 0.1);
    published += processor.process(jointState(stamp, names, positions)) ? 1 : 0;
  }
  return published;
}

TEST_F(JointStateProcessorTest, RateCapPublishesEachJointAtMostAtTheFrequency) {
  JointStateOptions capped = options();
  capped.publish_frequency = 50.0;
  JointStateProcessor processor(robot, capped);
  // 2 s of 1 kHz joint states with 0.3 ms of jitter: 100 batches at 50 Hz.
  const int published = publishedOf(processor, {"elbow_joint"}, kStamp, 1000, 2000, 300);
  EXPECT_GE(published, 99);
  EXPECT_LE(published, 101);
  EXPECT_EQ(processor.statistics().rate_limited, 2000u - static_cast<unsigned>(published));
  EXPECT_TRUE(reports.empty());
}

TEST_F(JointStateProcessorTest, RateCapKeepsSlowSourcesWhole) {
  JointStateOptions capped = options();
  capped.publish_frequency = 50.0;
  JointStateProcessor processor(robot, capped);
  int arm = 0;
  int gripper = 0;
  for (int k = 0; k < 2000; ++k) {  // arm at 1 kHz, gripper at 10 Hz, for 2 s
    const std::int64_t stamp = kStamp + k * 1000;
    arm += processor.process(jointState(stamp, {"elbow_joint"}, {0.1})) ? 1 : 0;
    if (k % 100 == 0) {
      gripper +=
          processor.process(jointState(stamp, {"gripper_left_finger_joint"}, {0.01})) ? 1 : 0;
    }
  }
  EXPECT_EQ(gripper, 20);
  EXPECT_GE(arm, 99);
  EXPECT_LE(arm, 101);
}

TEST_F(JointStateProcessorTest, RateCapHoldsForEachJointWhenSourcesShareMessages) {
  JointStateOptions capped = options();
  capped.publish_frequency = 50.0;
  JointStateProcessor processor(robot, capped);
  // The elbow alone at 0 ms, the head alone at 10 ms, then both together every 10 ms for 2 s:
  // each joint is due every 20 ms, on alternate messages, and must not ride along in between.
  processor.process(jointState(kStamp, {"elbow_joint"}, {0.1}));
  processor.process(jointState(kStamp + 10'000, {"head_pan_joint"}, {0.1}));
  std::map<std::string, int> published;
  for (int k = 2; k < 202; ++k) {
    const tf_message_t* batch = processor.process(
        jointState(kStamp + k * 10'000, {"elbow_joint", "head_pan_joint"}, {0.1, 0.2}));
    for (const std::string& child : children(batch)) ++published[child];
  }
  EXPECT_EQ(published["forearm_link"], 100);
  EXPECT_EQ(published["head_pan_link"], 100);
}

TEST_F(JointStateProcessorTest, RateCapStartsAfreshWhenStampsGoBack) {
  JointStateOptions capped = options();
  capped.publish_frequency = 10.0;
  JointStateProcessor processor(robot, capped);
  EXPECT_EQ(publishedOf(processor, {"elbow_joint"}, kStamp, 10'000, 100), 10);
  // The log starts over 10 s earlier: published at once, then at the cap again.
  EXPECT_EQ(publishedOf(processor, {"elbow_joint"}, kStamp - 10'000'000, 10'000, 100), 10);
}

TEST_F(JointStateProcessorTest, RateCapSurvivesStampsAtTheEndOfTime) {
  JointStateOptions capped = options();
  capped.publish_frequency = 10.0;
  JointStateProcessor processor(robot, capped);
  const std::int64_t last = std::numeric_limits<std::int64_t>::max();
  EXPECT_NE(processor.process(jointState(last - 5, {"elbow_joint"}, {0.1})), nullptr);
  processor.process(jointState(last, {"elbow_joint"}, {0.1}));  // no overflow (UBSan checks)
  EXPECT_NE(processor.process(jointState(kStamp, {"elbow_joint"}, {0.1})), nullptr);
}

TEST_F(JointStateProcessorTest, WithoutACapEveryJointStateIsPublished) {
  JointStateProcessor processor(robot, options());
  EXPECT_EQ(publishedOf(processor, {"elbow_joint"}, kStamp, 100, 500), 500);
}

TEST_F(JointStateProcessorTest, StatisticsSayWhatWasRefusedAndWhy) {
  JointStateProcessor processor(robot, options());
  processor.process(jointState(kStamp, {"elbow_joint", "ghost"}, {0.1, 0.2}));
  processor.process(jointState(kStamp, {"elbow_joint"}, {0.1, 0.2}));
  EXPECT_EQ(describe(processor.statistics()),
            "2 joint states, 1 batches of 1 transforms; 1 with names and positions differing in "
            "number; 1 unknown joint names");
  EXPECT_EQ(describe(JointStateStatistics{}), "0 joint states, 0 batches of 0 transforms");
}

}  // namespace
}  // namespace lcmtf::urdf
