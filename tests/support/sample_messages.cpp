#include "support/sample_messages.hpp"

#include <string>

namespace lcmtf_test {

lcmtf::transform_t sampleTransform(int seed) {
  const double s = seed;
  lcmtf::transform_t t{};
  t.utime = 1'700'000'000'000'001 + seed;
  t.parent_frame = "parent_" + std::to_string(seed);
  t.child_frame = "child_" + std::to_string(seed);
  t.translation.x = 1.5 + s;
  t.translation.y = -2.25 + s;
  t.translation.z = 3.125 + s;
  t.rotation.x = 0.1 + s;
  t.rotation.y = 0.2 + s;
  t.rotation.z = 0.3 + s;
  t.rotation.w = 0.4 + s;
  return t;
}

lcmtf::tf_message_t sampleTfMessage(int transforms) {
  lcmtf::tf_message_t message{};
  message.utime = 1'700'000'000'500'000;
  message.authority = "sample_broadcaster@host:4242";
  message.sequence = 4'000'000'017;
  for (int i = 0; i < transforms; ++i) message.transforms.push_back(sampleTransform(i));
  message.num_transforms = transforms;
  return message;
}

lcmtf::joint_state_t sampleJointState() {
  lcmtf::joint_state_t state{};
  state.utime = 1'700'000'000'250'000;
  state.authority = "sample_driver@host:4343";
  state.sequence = 5'000'000'019;
  state.name = {"shoulder", "elbow", "wrist"};
  state.num_joints = 3;
  state.position = {0.5, -1.25, 3.0};
  state.num_positions = 3;
  state.velocity = {0.01, 0.02, -0.03};
  state.num_velocities = 3;
  state.effort = {7.0, -8.0};
  state.num_efforts = 2;
  return state;
}

lcmtf::resend_request_t sampleResendRequest() {
  lcmtf::resend_request_t request{};
  request.utime = 1'700'000'000'750'000;
  request.requester = "listener@host:77";
  return request;
}

lcmtf::robot_description_t sampleRobotDescription() {
  lcmtf::robot_description_t description{};
  description.utime = 1'700'000'001'000'000;
  description.authority = "urdf_publisher@host:9";
  description.robot_name = "sample_bot";
  description.urdf = "<robot name=\"sample_bot\"><link name=\"base\"/></robot>";
  return description;
}

void expectEqual(const lcmtf::transform_t& actual, const lcmtf::transform_t& expected) {
  EXPECT_EQ(actual.utime, expected.utime);
  EXPECT_EQ(actual.parent_frame, expected.parent_frame);
  EXPECT_EQ(actual.child_frame, expected.child_frame);
  EXPECT_EQ(actual.translation.x, expected.translation.x);
  EXPECT_EQ(actual.translation.y, expected.translation.y);
  EXPECT_EQ(actual.translation.z, expected.translation.z);
  EXPECT_EQ(actual.rotation.x, expected.rotation.x);
  EXPECT_EQ(actual.rotation.y, expected.rotation.y);
  EXPECT_EQ(actual.rotation.z, expected.rotation.z);
  EXPECT_EQ(actual.rotation.w, expected.rotation.w);
}

void expectEqual(const lcmtf::tf_message_t& actual, const lcmtf::tf_message_t& expected) {
  EXPECT_EQ(actual.utime, expected.utime);
  EXPECT_EQ(actual.authority, expected.authority);
  EXPECT_EQ(actual.sequence, expected.sequence);
  EXPECT_EQ(actual.num_transforms, expected.num_transforms);
  ASSERT_EQ(actual.transforms.size(), expected.transforms.size());
  for (std::size_t i = 0; i < actual.transforms.size(); ++i) {
    SCOPED_TRACE("transforms[" + std::to_string(i) + "]");
    expectEqual(actual.transforms[i], expected.transforms[i]);
  }
}

void expectEqual(const lcmtf::joint_state_t& actual, const lcmtf::joint_state_t& expected) {
  EXPECT_EQ(actual.utime, expected.utime);
  EXPECT_EQ(actual.authority, expected.authority);
  EXPECT_EQ(actual.sequence, expected.sequence);
  EXPECT_EQ(actual.num_joints, expected.num_joints);
  EXPECT_EQ(actual.name, expected.name);
  EXPECT_EQ(actual.num_positions, expected.num_positions);
  EXPECT_EQ(actual.position, expected.position);
  EXPECT_EQ(actual.num_velocities, expected.num_velocities);
  EXPECT_EQ(actual.velocity, expected.velocity);
  EXPECT_EQ(actual.num_efforts, expected.num_efforts);
  EXPECT_EQ(actual.effort, expected.effort);
}

void expectEqual(const lcmtf::resend_request_t& actual, const lcmtf::resend_request_t& expected) {
  EXPECT_EQ(actual.utime, expected.utime);
  EXPECT_EQ(actual.requester, expected.requester);
}

void expectEqual(const lcmtf::robot_description_t& actual,
                 const lcmtf::robot_description_t& expected) {
  EXPECT_EQ(actual.utime, expected.utime);
  EXPECT_EQ(actual.authority, expected.authority);
  EXPECT_EQ(actual.robot_name, expected.robot_name);
  EXPECT_EQ(actual.urdf, expected.urdf);
}

}  // namespace lcmtf_test
