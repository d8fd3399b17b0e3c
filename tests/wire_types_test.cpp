#include <gtest/gtest.h>

#include "lcmtf/wire_decode.hpp"
#include "support/sample_messages.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::encode;
using lcmtf_test::expectEqual;

// Encodes with lcm-gen's code, then decodes twice: with lcm-gen's decode and with the checked
// decodeMessage. Both must give back every field.
template <class Message>
void expectRoundTrip(const Message& original) {
  const std::vector<std::uint8_t> bytes = encode(original);
  ASSERT_EQ(bytes.size(), static_cast<std::size_t>(original.getEncodedSize()));

  Message generated_decode;
  ASSERT_EQ(generated_decode.decode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  {
    SCOPED_TRACE("lcm-gen decode");
    expectEqual(generated_decode, original);
  }

  Message checked_decode;
  const DecodeResult result = decodeMessage(bytes.data(), bytes.size(), checked_decode);
  ASSERT_TRUE(result.ok) << result.error;
  SCOPED_TRACE("decodeMessage");
  expectEqual(checked_decode, original);
}

TEST(WireTypes, TransformRoundTripsEveryField) { expectRoundTrip(lcmtf_test::sampleTransform(7)); }

TEST(WireTypes, TfMessageRoundTripsEveryField) { expectRoundTrip(lcmtf_test::sampleTfMessage(5)); }

TEST(WireTypes, EmptyTfMessageRoundTrips) { expectRoundTrip(lcmtf_test::sampleTfMessage(0)); }

TEST(WireTypes, JointStateRoundTripsEveryField) { expectRoundTrip(lcmtf_test::sampleJointState()); }

TEST(WireTypes, JointStateWithoutVelocityAndEffortRoundTrips) {
  joint_state_t state = lcmtf_test::sampleJointState();
  state.velocity.clear();
  state.num_velocities = 0;
  state.effort.clear();
  state.num_efforts = 0;
  expectRoundTrip(state);
}

TEST(WireTypes, ResendRequestRoundTripsEveryField) {
  expectRoundTrip(lcmtf_test::sampleResendRequest());
}

TEST(WireTypes, RobotDescriptionRoundTripsEveryField) {
  expectRoundTrip(lcmtf_test::sampleRobotDescription());
}

TEST(WireTypes, LargeRobotDescriptionRoundTrips) {
  robot_description_t description = lcmtf_test::sampleRobotDescription();
  description.urdf = std::string(2'000'000, 'x');
  expectRoundTrip(description);
}

TEST(WireTypes, SixtyTransformBatchFitsOneDatagram) {
  tf_message_t batch = lcmtf_test::sampleTfMessage(0);
  for (int i = 0; i < 60; ++i) {
    transform_t t = lcmtf_test::sampleTransform(i);
    t.parent_frame = "robot/link_with_a_long_descriptive_name_" + std::to_string(i);
    t.child_frame = "robot/link_with_a_long_descriptive_name_" + std::to_string(i + 1);
    batch.transforms.push_back(t);
  }
  batch.num_transforms = 60;
  EXPECT_LT(batch.getEncodedSize(), 65000);
}

// A change to a .lcm file changes its fingerprint and breaks every deployed peer; these pins
// make such a change deliberate.
TEST(WireTypes, FingerprintsAreStable) {
  EXPECT_EQ(static_cast<std::uint64_t>(transform_t::getHash()), 0x7f66103c6461dcbcull);
  EXPECT_EQ(static_cast<std::uint64_t>(tf_message_t::getHash()), 0x06e6a51c6ce8553aull);
  EXPECT_EQ(static_cast<std::uint64_t>(joint_state_t::getHash()), 0xd1c28c65bafca4abull);
  EXPECT_EQ(static_cast<std::uint64_t>(resend_request_t::getHash()), 0x9a59296425c71ef0ull);
  EXPECT_EQ(static_cast<std::uint64_t>(robot_description_t::getHash()), 0xfe4bc05125116998ull);
}

}  // namespace
}  // namespace lcmtf
