// The publisher on one in-process LCM (memq): statics and description at start and on request,
// joint states in and batches out, channels as configured, and the wait for a description.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "joint_state_helpers.hpp"
#include "lcmtf/message_conversions.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf/wire_decode.hpp"
#include "lcmtf_urdf/joint_motion.hpp"
#include "lcmtf_urdf/robot_description.hpp"
#include "lcmtf_urdf/urdf_publisher.hpp"

namespace lcmtf::urdf {
namespace {

using lcmtf_test::jointState;
using namespace std::chrono_literals;
using testing::HasSubstr;

constexpr std::int64_t kStamp = 1'700'000'000'000'000;

// Every message of type Message on one channel, decoded, and how many did not decode.
template <class Message>
struct Recorder {
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
    Message message;
    if (decodeMessage(buffer->data, buffer->data_size, message).ok) {
      messages.push_back(message);
    } else {
      ++undecodable;
    }
  }
  std::vector<Message> messages;
  int undecodable = 0;
};

std::string twoLinkUrdf(const std::string& parent, const std::string& child) {
  return "<robot name='two'><link name='" + parent + "'/><link name='" + child +
         "'/><joint name='j' type='continuous'><parent link='" + parent + "'/><child link='" +
         child + "'/></joint></robot>";
}

resend_request_t request() {
  resend_request_t message{};
  message.utime = kStamp;
  message.requester = "test";
  return message;
}

class UrdfPublisherTest : public testing::Test {
 protected:
  UrdfPublisherTest() {
    lcm_.subscribe(kTfChannel, &Recorder<tf_message_t>::onMessage, &tf_);
    lcm_.subscribe(kTfStaticChannel, &Recorder<tf_message_t>::onMessage, &statics_);
    lcm_.subscribe(kRobotDescriptionChannel, &Recorder<robot_description_t>::onMessage,
                   &descriptions_);
  }

  void handleAll() {
    while (lcm_.handleTimeout(0) > 0) {
    }
  }

  UrdfPublisherOptions options() {
    UrdfPublisherOptions result;
    result.joint_states.authority = "publisher-under-test";
    result.joint_states.reporter = [this](const std::string& m) { reports_.push_back(m); };
    return result;
  }

  lcm::LCM lcm_{"memq://"};
  const RobotModel robot_ = loadRobotModel(EXAMPLE_URDF);
  Recorder<tf_message_t> tf_;
  Recorder<tf_message_t> statics_;
  Recorder<robot_description_t> descriptions_;
  std::vector<std::string> reports_;
};

TEST_F(UrdfPublisherTest, FixedJointsAndTheDescriptionGoOutAtStart) {
  UrdfPublisher publisher(lcm_, robot_, options());
  handleAll();
  ASSERT_EQ(statics_.messages.size(), 1u);
  const tf_message_t& statics = statics_.messages[0];
  EXPECT_EQ(statics.authority, "publisher-under-test");
  ASSERT_EQ(statics.transforms.size(), robot_.fixed_joints.size());
  for (const FixedJoint& joint : robot_.fixed_joints) {
    bool found = false;
    for (const transform_t& t : statics.transforms) {
      if (t.child_frame != joint.child_link) continue;
      found = true;
      EXPECT_EQ(t.parent_frame, joint.parent_link);
      EXPECT_TRUE(fromMessage(t).transform.isApprox(joint.parent_T_child)) << joint.name;
    }
    EXPECT_TRUE(found) << joint.name;
  }
  ASSERT_EQ(descriptions_.messages.size(), 1u);
  EXPECT_EQ(descriptions_.messages[0].urdf, robot_.urdf);
  EXPECT_EQ(descriptions_.messages[0].robot_name, "mobile_manipulator");
  EXPECT_EQ(descriptions_.messages[0].authority, "publisher-under-test");
  EXPECT_TRUE(tf_.messages.empty());
}

TEST_F(UrdfPublisherTest, EachJointStateBecomesOneBatchOnTf) {
  UrdfPublisher publisher(lcm_, robot_, options());
  for (int k = 0; k < 3; ++k) {
    const joint_state_t state =
        jointState(kStamp + k, {{"elbow_joint", 0.1 * k}, {"gripper_left_finger_joint", 0.02}});
    lcm_.publish(kJointStatesChannel, &state);
  }
  handleAll();
  ASSERT_EQ(tf_.messages.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const tf_message_t& batch = tf_.messages[static_cast<std::size_t>(k)];
    ASSERT_EQ(batch.transforms.size(), 3u);  // elbow, left finger, right finger
    for (const transform_t& t : batch.transforms) EXPECT_EQ(t.utime, kStamp + k);
    EXPECT_TRUE(
        fromMessage(batch.transforms[0])
            .transform.isApprox(parentTChild(*robot_.findMovableJoint("elbow_joint"), 0.1 * k)));
  }
  EXPECT_EQ(publisher.statistics().batches, 3u);
  EXPECT_EQ(publisher.publishFailures(), 0u);
}

// Two drivers number their joint states apart; those that never came are counted, and the
// batches on TF go out numbered one after another.
TEST_F(UrdfPublisherTest, JointStatesThatNeverCameAreCountedPerSenderAndBatchesAreNumbered) {
  UrdfPublisher publisher(lcm_, robot_, options());
  const auto publish = [&](const std::string& authority, std::int64_t sequence,
                           const std::string& joint) {
    joint_state_t state = jointState(kStamp + sequence, {{joint, 0.1}});
    state.authority = authority;
    state.sequence = sequence;
    lcm_.publish(kJointStatesChannel, &state);
  };
  for (std::int64_t n : {1, 2, 5, 6, 4}) publish("arm_driver", n, "elbow_joint");
  for (std::int64_t n : {1, 2, 2, 3}) publish("gripper_driver", n, "gripper_left_finger_joint");
  handleAll();
  EXPECT_EQ(publisher.statistics().lost, 1u);
  EXPECT_EQ(publisher.statistics().reordered, 1u);
  EXPECT_EQ(publisher.statistics().duplicated, 1u);
  EXPECT_THAT(describe(publisher.statistics()),
              HasSubstr("1 lost on the way (numbers skipped); 1 came out of order; 1 came twice"));
  ASSERT_EQ(tf_.messages.size(), 9u);
  for (std::size_t k = 0; k < tf_.messages.size(); ++k) {
    EXPECT_EQ(tf_.messages[k].sequence, static_cast<std::int64_t>(k + 1));
  }
  ASSERT_FALSE(statics_.messages.empty());
  EXPECT_EQ(statics_.messages[0].sequence, 1);
}

TEST_F(UrdfPublisherTest, BadJointStatesOnTheNetworkAreCountedAndReported) {
  UrdfPublisher publisher(lcm_, robot_, options());
  const std::vector<std::uint8_t> garbage(40, 0xab);
  lcm_.publish(kJointStatesChannel, garbage.data(), static_cast<unsigned>(garbage.size()));
  const joint_state_t unknown = jointState(kStamp, {{"ghost", 1.0}});
  lcm_.publish(kJointStatesChannel, &unknown);
  handleAll();
  EXPECT_TRUE(tf_.messages.empty());
  EXPECT_EQ(publisher.statistics().malformed, 1u);
  EXPECT_EQ(publisher.statistics().unknown_joints, 1u);
  ASSERT_EQ(reports_.size(), 2u);
  EXPECT_THAT(reports_[0], HasSubstr("does not decode"));
  EXPECT_THAT(reports_[1], HasSubstr("'ghost'"));
}

// LCM holds fewer joint states while large ones come (what it holds: ListenerQueue tests).
TEST_F(UrdfPublisherTest, LargeJointStatesShortenTheQueueOfThemLcmHolds) {
  UrdfPublisherOptions shortened = options();
  shortened.queue_bytes = 100'000;
  UrdfPublisher publisher(lcm_, robot_, shortened);
  const joint_state_t state = jointState(kStamp, {{"elbow_joint", 0.1}});
  lcm_.publish(kJointStatesChannel, &state);
  handleAll();
  EXPECT_EQ(publisher.jointStateQueueShortened(), 0u);

  const std::vector<char> large(60'000, 'x');
  lcm_.publish(kJointStatesChannel, large.data(), static_cast<unsigned int>(large.size()));
  lcm_.publish(kJointStatesChannel, large.data(), static_cast<unsigned int>(large.size()));
  lcm_.publish(kJointStatesChannel, &state);
  handleAll();
  EXPECT_EQ(publisher.jointStateQueueShortened(), 1u);
  EXPECT_EQ(publisher.statistics().batches, 2u);
}

TEST_F(UrdfPublisherTest, TheDescriptionIsSentAgainWhenAsked) {
  UrdfPublisher publisher(lcm_, robot_, options());
  handleAll();
  const resend_request_t ask = request();
  lcm_.publish(kRobotDescriptionRequestChannel, &ask);
  const std::vector<std::uint8_t> garbage(5, 1);
  lcm_.publish(kRobotDescriptionRequestChannel, garbage.data(), 5);
  handleAll();
  EXPECT_EQ(descriptions_.messages.size(), 2u);
  EXPECT_EQ(publisher.descriptionRequestsAnswered(), 1u);
}

TEST_F(UrdfPublisherTest, AFloodOfDescriptionRequestsIsAnsweredAtAModestRate) {
  UrdfPublisher publisher(lcm_, robot_, options());
  handleAll();
  const resend_request_t ask = request();
  for (int i = 0; i < 50; ++i) lcm_.publish(kRobotDescriptionRequestChannel, &ask);
  handleAll();
  EXPECT_EQ(descriptions_.messages.size(), 2u) << "the first request is answered at once";
  EXPECT_EQ(publisher.descriptionRequestsAnswered(), 50u);
  publisher.poll();
  handleAll();
  EXPECT_EQ(descriptions_.messages.size(), 2u);
  std::this_thread::sleep_for(UrdfPublisher::kDescriptionAnswerInterval + 10ms);
  publisher.poll();
  handleAll();
  EXPECT_EQ(descriptions_.messages.size(), 3u) << "the others share one later answer";
  EXPECT_EQ(publisher.descriptionAnswersSent(), 2u);
  publisher.poll();
  handleAll();
  EXPECT_EQ(descriptions_.messages.size(), 3u);
}

TEST_F(UrdfPublisherTest, StaticsAreSentAgainWhenAListenerAsksAndEveryPeriod) {
  UrdfPublisherOptions periodic = options();
  periodic.static_resend_period = 50ms;
  UrdfPublisher publisher(lcm_, robot_, periodic);
  handleAll();
  const resend_request_t ask = request();
  lcm_.publish(kTfStaticRequestChannel, &ask);
  handleAll();
  EXPECT_EQ(statics_.messages.size(), 2u);
  publisher.poll();
  handleAll();
  EXPECT_EQ(statics_.messages.size(), 2u);
  std::this_thread::sleep_for(60ms);
  publisher.poll();
  handleAll();
  EXPECT_EQ(statics_.messages.size(), 3u);
}

TEST_F(UrdfPublisherTest, ADescriptionFromTheNetworkIsNotRepublished) {
  UrdfPublisherOptions received = options();
  received.publish_description = false;
  UrdfPublisher publisher(lcm_, robot_, received);
  const resend_request_t ask = request();
  lcm_.publish(kRobotDescriptionRequestChannel, &ask);
  handleAll();
  EXPECT_TRUE(descriptions_.messages.empty());
  EXPECT_EQ(statics_.messages.size(), 1u);
}

TEST_F(UrdfPublisherTest, ANewDescriptionReplacesTheRobotAndItsStatics) {
  UrdfPublisherOptions following = options();
  following.publish_description = false;
  following.follow_description = true;
  UrdfPublisher publisher(lcm_, robot_, following);
  handleAll();
  const robot_description_t small = makeRobotDescription(
      parseRobotModel("<robot name='small'><link name='a'/><link name='b'/><link name='c'/>"
                      "<joint name='mount' type='fixed'><parent link='a'/><child link='b'/>"
                      "</joint><joint name='j1' type='continuous'><parent link='b'/>"
                      "<child link='c'/></joint></robot>",
                      "test"),
      "owner");
  for (int k = 0; k < 2; ++k) {  // the same description again changes nothing
    lcm_.publish(kRobotDescriptionChannel, &small);
    handleAll();
    publisher.poll();
    handleAll();
  }
  EXPECT_EQ(publisher.robotsReplaced(), 1u);
  EXPECT_EQ(publisher.robot().name, "small");
  const resend_request_t ask = request();
  lcm_.publish(kTfStaticRequestChannel, &ask);
  handleAll();
  ASSERT_GE(statics_.messages.size(), 2u);
  for (const tf_message_t* answer : {&statics_.messages[1], &statics_.messages.back()}) {
    ASSERT_EQ(answer->transforms.size(), 1u) << "the old robot's statics are sent no more";
    EXPECT_EQ(answer->transforms[0].child_frame, "b");
  }
  const joint_state_t state = jointState(kStamp, {{"j1", 0.5}, {"elbow_joint", 0.1}});
  lcm_.publish(kJointStatesChannel, &state);
  handleAll();
  ASSERT_EQ(tf_.messages.size(), 1u);
  ASSERT_EQ(tf_.messages[0].transforms.size(), 1u);
  EXPECT_EQ(tf_.messages[0].transforms[0].child_frame, "c");
  EXPECT_EQ(publisher.statistics().unknown_joints, 1u);
}

TEST_F(UrdfPublisherTest, ABadNewDescriptionKeepsTheRobotAndIsReportedOnce) {
  UrdfPublisherOptions following = options();
  following.follow_description = true;
  UrdfPublisher publisher(lcm_, robot_, following);
  robot_description_t broken = makeRobotDescription(robot_, "owner");
  broken.urdf = "<robot name='broken'><link name='a'/>";
  for (int k = 0; k < 3; ++k) {
    lcm_.publish(kRobotDescriptionChannel, &broken);
    handleAll();
    publisher.poll();
  }
  EXPECT_EQ(publisher.robotsReplaced(), 0u);
  EXPECT_EQ(publisher.robot().name, "mobile_manipulator");
  EXPECT_EQ(publisher.descriptionsRefused(), 1u);
  ASSERT_EQ(reports_.size(), 1u);
  EXPECT_THAT(reports_[0], HasSubstr("kept the robot, refused a new robot description: "));
}

TEST_F(UrdfPublisherTest, ANewDescriptionWhoseLinksThePrefixMakesTooLongIsRefused) {
  UrdfPublisherOptions following = options();
  following.follow_description = true;
  following.joint_states.frame_prefix = std::string(250, 'p');
  UrdfPublisher publisher(lcm_, parseRobotModel(twoLinkUrdf("a", "b"), "test"), following);
  robot_description_t longer = makeRobotDescription(robot_, "owner");
  longer.urdf = twoLinkUrdf("a", "gripper");
  lcm_.publish(kRobotDescriptionChannel, &longer);
  handleAll();
  publisher.poll();
  EXPECT_EQ(publisher.robotsReplaced(), 0u);
  EXPECT_EQ(publisher.descriptionsRefused(), 1u);
  ASSERT_EQ(reports_.size(), 1u);
  EXPECT_THAT(reports_[0], HasSubstr("frame prefix and link 'ppp"));
  EXPECT_THAT(reports_[0], HasSubstr("is 257 bytes long"));
}

TEST_F(UrdfPublisherTest, APrefixThatMakesALinkTooLongIsRefusedAtTheStart) {
  UrdfPublisherOptions prefixed = options();
  prefixed.joint_states.frame_prefix = std::string(250, 'p');
  EXPECT_THROW(UrdfPublisher(lcm_, parseRobotModel(twoLinkUrdf("a", "gripper"), "test"), prefixed),
               UrdfError);
  UrdfPublisherOptions signed_long = options();
  signed_long.joint_states.authority = std::string(257, 's');
  EXPECT_THROW(UrdfPublisher(lcm_, robot_, signed_long), std::invalid_argument);
  handleAll();
  EXPECT_TRUE(statics_.messages.empty());
  EXPECT_TRUE(descriptions_.messages.empty());
}

TEST_F(UrdfPublisherTest, EveryChannelCanBeChanged) {
  UrdfPublisherOptions renamed = options();
  renamed.joint_states_channel = "ARM_JOINTS";
  renamed.tf_channel = "ARM_TF";
  renamed.tf_static_channel = "ARM_TF_STATIC";
  renamed.description_channel = "ARM_DESCRIPTION";
  Recorder<tf_message_t> tf;
  Recorder<tf_message_t> statics;
  Recorder<robot_description_t> descriptions;
  lcm_.subscribe("ARM_TF", &Recorder<tf_message_t>::onMessage, &tf);
  lcm_.subscribe("ARM_TF_STATIC", &Recorder<tf_message_t>::onMessage, &statics);
  lcm_.subscribe("ARM_DESCRIPTION", &Recorder<robot_description_t>::onMessage, &descriptions);
  UrdfPublisher publisher(lcm_, robot_, renamed);
  const joint_state_t state = jointState(kStamp, {{"elbow_joint", 0.3}});
  lcm_.publish("ARM_JOINTS", &state);
  lcm_.publish(kJointStatesChannel, &state);
  handleAll();
  EXPECT_EQ(tf.messages.size(), 1u);
  EXPECT_EQ(statics.messages.size(), 1u);
  EXPECT_EQ(descriptions.messages.size(), 1u);
  EXPECT_TRUE(tf_.messages.empty());
  EXPECT_TRUE(statics_.messages.empty());
  EXPECT_TRUE(descriptions_.messages.empty());
}

TEST_F(UrdfPublisherTest, AListenerOnTheSameLcmLooksUpTheGripperInTheBase) {
  UrdfPublisher publisher(lcm_, robot_, options());
  Buffer buffer;
  TransformListener listener(buffer, lcm_);
  handleAll();  // the listener's request brings the statics again
  std::map<std::string, double> positions{{"shoulder_pan_joint", 0.4},
                                          {"shoulder_lift_joint", -0.7},
                                          {"elbow_joint", 1.1},
                                          {"wrist_1_joint", 0.3},
                                          {"wrist_2_joint", -1.2},
                                          {"wrist_3_joint", 2.0},
                                          {"gripper_left_finger_joint", 0.01}};
  const joint_state_t state = jointState(kStamp, positions);
  lcm_.publish(kJointStatesChannel, &state);
  handleAll();

  Transform expected;  // base_link -> gripper_tcp through the model, joint by joint
  const std::vector<std::string> chain{
      "arm_mount_joint",     "shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
      "wrist_1_joint",       "wrist_2_joint",      "wrist_3_joint",       "tool_flange_joint",
      "gripper_mount_joint", "gripper_tcp_joint"};
  for (const std::string& name : chain) {
    if (const MovableJoint* joint = robot_.findMovableJoint(name)) {
      expected = expected * parentTChild(*joint, positions.at(name));
    } else {
      for (const FixedJoint& fixed : robot_.fixed_joints) {
        if (fixed.name == name) expected = expected * fixed.parent_T_child;
      }
    }
  }
  const TransformStamped got = buffer.lookupTransform("base_link", "gripper_tcp", kLatestTime);
  EXPECT_EQ(got.stamp, fromUtime(kStamp));
  EXPECT_TRUE(got.transform.isApprox(expected, 1e-12));
}

// Answers each request for the description with `answer`, after `before` (bad ones first).
struct DescriptionResponder {
  void onRequest(const lcm::ReceiveBuffer* /*buffer*/, const std::string& /*channel*/) {
    ++requests;
    for (const std::vector<std::uint8_t>& bytes : before) {
      lcm->publish(kRobotDescriptionChannel, bytes.data(), static_cast<unsigned>(bytes.size()));
    }
    lcm->publish(kRobotDescriptionChannel, &answer);
  }
  lcm::LCM* lcm = nullptr;
  std::vector<std::vector<std::uint8_t>> before;
  robot_description_t answer{};
  int requests = 0;
};

TEST_F(UrdfPublisherTest, WaitingForADescriptionAsksAndSkipsAndCountsBadOnes) {
  DescriptionResponder responder;
  responder.lcm = &lcm_;
  robot_description_t bad = makeRobotDescription(robot_, "responder");
  bad.urdf =
      "<robot name='r'><link name='a'/><link name='b'/><joint name='j' type='continuous'>"
      "<parent link='a'/><child link='b'/><axis xyz='0 0 0'/></joint></robot>";
  std::vector<std::uint8_t> bad_bytes(static_cast<std::size_t>(bad.getEncodedSize()));
  bad.encode(bad_bytes.data(), 0, static_cast<int>(bad_bytes.size()));
  responder.before = {std::vector<std::uint8_t>(12, 7), bad_bytes};
  responder.answer = makeRobotDescription(robot_, "responder");
  lcm_.subscribe(kRobotDescriptionRequestChannel, &DescriptionResponder::onRequest, &responder);

  DescriptionWaitOptions wait;
  std::vector<std::string> refusals;
  wait.reporter = [&refusals](const std::string& message) { refusals.push_back(message); };
  std::atomic<bool> stop{false};
  DescriptionWaitStatistics heard;
  const std::optional<RobotModel> robot = waitForRobotDescription(lcm_, wait, stop, &heard);
  ASSERT_TRUE(robot);
  EXPECT_EQ(heard.received, 3u);
  EXPECT_EQ(heard.refused, 2u);
  EXPECT_EQ(robot->name, "mobile_manipulator");
  EXPECT_EQ(robot->source, "ROBOT_DESCRIPTION from responder");
  EXPECT_EQ(robot->movable_joints.size(), robot_.movable_joints.size());
  EXPECT_EQ(responder.requests, 1);
  ASSERT_EQ(refusals.size(), 2u);
  EXPECT_THAT(refusals[0], HasSubstr("refused a message on ROBOT_DESCRIPTION: "));
  EXPECT_EQ(refusals[1],
            "refused a robot description: ROBOT_DESCRIPTION from responder: joint 'j' has a zero "
            "axis (0 0 0): it cannot say which way the joint moves");
}

TEST_F(UrdfPublisherTest, WaitingForADescriptionAsksAgainAndEndsWhenStopped) {
  lcm::LCM silent("memq://");
  struct Count {
    void onRequest(const lcm::ReceiveBuffer*, const std::string&) { ++requests; }
    std::atomic<int> requests{0};
  } count;
  silent.subscribe(kRobotDescriptionRequestChannel, &Count::onRequest, &count);
  DescriptionWaitOptions wait;
  wait.request_period = 30ms;
  std::atomic<bool> stop{false};
  auto waiting =
      std::async(std::launch::async, [&] { return waitForRobotDescription(silent, wait, stop); });
  std::this_thread::sleep_for(200ms);
  stop = true;
  ASSERT_EQ(waiting.wait_for(1s), std::future_status::ready);
  EXPECT_FALSE(waiting.get());
  EXPECT_GE(count.requests, 3);
}

}  // namespace
}  // namespace lcmtf::urdf
