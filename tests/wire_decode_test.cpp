#include "lcmtf/wire_decode.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "support/sample_messages.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::encode;
using testing::HasSubstr;

void putInt32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::int32_t value) {
  const auto bits = static_cast<std::uint32_t>(value);
  for (int i = 0; i < 4; ++i) {
    bytes[offset + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(bits >> (24 - 8 * i));
  }
}

// Where sequence sits in an encoded tf_message_t: after the fingerprint, utime, authority string.
std::size_t sequenceOffset(const tf_message_t& message) {
  return 8 + 8 + 4 + message.authority.size() + 1;
}

// Where num_transforms sits: after the sequence.
std::size_t countOffset(const tf_message_t& message) { return sequenceOffset(message) + 8; }

template <class Message>
std::string decodeError(const std::vector<std::uint8_t>& bytes, const DecodeLimits& limits = {}) {
  Message out;
  const DecodeResult result = decodeMessage(bytes.data(), bytes.size(), out, limits);
  EXPECT_FALSE(result.ok) << "bad bytes were accepted";
  return result.error;
}

TEST(WireDecode, EveryTruncationFailsAndSaysTruncated) {
  const std::vector<std::uint8_t> bytes = encode(lcmtf_test::sampleTfMessage(3));
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const std::vector<std::uint8_t> prefix(bytes.begin(),
                                           bytes.begin() + static_cast<long>(length));
    EXPECT_THAT(decodeError<tf_message_t>(prefix), HasSubstr("truncated")) << length;
  }
}

TEST(WireDecode, EveryJointStateTruncationFails) {
  const std::vector<std::uint8_t> bytes = encode(lcmtf_test::sampleJointState());
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const std::vector<std::uint8_t> prefix(bytes.begin(),
                                           bytes.begin() + static_cast<long>(length));
    EXPECT_FALSE(decodeError<joint_state_t>(prefix).empty()) << length;
  }
}

TEST(WireDecode, EmptyInputFails) {
  tf_message_t out;
  const DecodeResult result = decodeMessage(nullptr, 0, out);
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.error, "tf_message_t: fingerprint: truncated: needs 8 bytes, 0 remain");
}

TEST(WireDecode, WrongTypeIsRejectedByFingerprint) {
  const std::vector<std::uint8_t> bytes = encode(lcmtf_test::sampleJointState());
  const std::string error = decodeError<tf_message_t>(bytes);
  EXPECT_THAT(error, HasSubstr("tf_message_t: fingerprint 0x"));
  EXPECT_THAT(error, HasSubstr("another type"));
}

TEST(WireDecode, NegativeCountIsRejected) {
  const tf_message_t message = lcmtf_test::sampleTfMessage(2);
  std::vector<std::uint8_t> bytes = encode(message);
  putInt32(bytes, countOffset(message), -5);
  EXPECT_EQ(decodeError<tf_message_t>(bytes), "tf_message_t: num_transforms: negative count -5");
}

TEST(WireDecode, CountClaimingMillionsIsRejectedBeforeAllocating) {
  const tf_message_t message = lcmtf_test::sampleTfMessage(2);
  std::vector<std::uint8_t> bytes = encode(message);
  putInt32(bytes, countOffset(message), 5'000'000);
  EXPECT_EQ(decodeError<tf_message_t>(bytes),
            "tf_message_t: num_transforms: count 5000000 exceeds the limit of 65536");

  putInt32(bytes, countOffset(message), 60'000);
  EXPECT_THAT(decodeError<tf_message_t>(bytes),
              HasSubstr("num_transforms: truncated: count 60000 needs at least 4440000 bytes"));
}

TEST(WireDecode, CountLimitIsConfigurable) {
  const std::vector<std::uint8_t> bytes = encode(lcmtf_test::sampleTfMessage(3));
  DecodeLimits limits;
  limits.max_array_elements = 2;
  EXPECT_EQ(decodeError<tf_message_t>(bytes, limits),
            "tf_message_t: num_transforms: count 3 exceeds the limit of 2");
}

TEST(WireDecode, OverlongFrameNameIsRejectedNamingTheField) {
  tf_message_t message = lcmtf_test::sampleTfMessage(3);
  message.transforms[1].child_frame = std::string(300, 'a');
  EXPECT_EQ(decodeError<tf_message_t>(encode(message)),
            "tf_message_t: transforms[1].child_frame: string of 300 bytes exceeds the limit of "
            "256 bytes");
}

TEST(WireDecode, NameAtTheLimitIsAccepted) {
  tf_message_t message = lcmtf_test::sampleTfMessage(1);
  message.transforms[0].parent_frame = std::string(256, 'p');
  tf_message_t out;
  const std::vector<std::uint8_t> bytes = encode(message);
  EXPECT_TRUE(decodeMessage(bytes.data(), bytes.size(), out).ok);
  EXPECT_EQ(out.transforms[0].parent_frame, message.transforms[0].parent_frame);
}

TEST(WireDecode, OverlongJointNameIsRejected) {
  joint_state_t state = lcmtf_test::sampleJointState();
  state.name[2] = std::string(1000, 'j');
  EXPECT_EQ(decodeError<joint_state_t>(encode(state)),
            "joint_state_t: name[2].name: string of 1000 bytes exceeds the limit of 256 bytes");
}

TEST(WireDecode, StringLengthZeroOrNegativeIsRejected) {
  const tf_message_t message = lcmtf_test::sampleTfMessage(1);
  for (std::int32_t length : {0, -1, -100000}) {
    std::vector<std::uint8_t> bytes = encode(message);
    putInt32(bytes, 16, length);
    EXPECT_EQ(decodeError<tf_message_t>(bytes), "tf_message_t: authority: string length field is " +
                                                    std::to_string(length) +
                                                    " (at least 1 for the terminating NUL)");
  }
}

TEST(WireDecode, StringWithoutTerminatorOrWithInnerNulIsRejected) {
  const tf_message_t message = lcmtf_test::sampleTfMessage(1);
  std::vector<std::uint8_t> bytes = encode(message);
  bytes[sequenceOffset(message) - 1] = 'x';
  EXPECT_EQ(decodeError<tf_message_t>(bytes),
            "tf_message_t: authority: string is not NUL-terminated");

  bytes = encode(message);
  bytes[22] = 0;
  EXPECT_EQ(decodeError<tf_message_t>(bytes),
            "tf_message_t: authority: string contains a NUL byte");
}

TEST(WireDecode, StringLongerThanTheBufferIsTruncation) {
  robot_description_t description = lcmtf_test::sampleRobotDescription();
  std::vector<std::uint8_t> bytes = encode(description);
  const std::size_t urdf_length_offset =
      8 + 8 + (4 + description.authority.size() + 1) + (4 + description.robot_name.size() + 1);
  putInt32(bytes, urdf_length_offset, 1'000'000'000);
  EXPECT_THAT(decodeError<robot_description_t>(bytes),
              HasSubstr("robot_description_t: urdf: truncated: needs 1000000000 bytes"));
}

TEST(WireDecode, TrailingBytesAreRejected) {
  std::vector<std::uint8_t> bytes = encode(lcmtf_test::sampleResendRequest());
  bytes.push_back(0);
  EXPECT_EQ(decodeError<resend_request_t>(bytes),
            "resend_request_t: 1 unexpected bytes after the end of the message");
}

TEST(WireDecode, FailedDecodeOfJointStateNamesPositionCount) {
  joint_state_t state = lcmtf_test::sampleJointState();
  std::vector<std::uint8_t> bytes = encode(state);
  std::size_t offset = 8 + 8 + (4 + state.authority.size() + 1) + 8 + 4;
  for (const std::string& name : state.name) offset += 4 + name.size() + 1;
  putInt32(bytes, offset, 1000);
  EXPECT_THAT(decodeError<joint_state_t>(bytes),
              HasSubstr("joint_state_t: num_positions: truncated: count 1000 needs"));
}

TEST(WireDecode, AReusedMessageKeepsNothingOfThePreviousOneWhereTheNewOneIsEmpty) {
  joint_state_t state;
  const std::vector<std::uint8_t> full = encode(lcmtf_test::sampleJointState());
  ASSERT_TRUE(decodeMessage(full.data(), full.size(), state).ok);
  ASSERT_FALSE(state.position.empty());
  joint_state_t names_only = lcmtf_test::sampleJointState();
  names_only.num_positions = names_only.num_velocities = names_only.num_efforts = 0;
  names_only.position.clear();
  names_only.velocity.clear();
  names_only.effort.clear();
  const std::vector<std::uint8_t> bytes = encode(names_only);
  ASSERT_TRUE(decodeMessage(bytes.data(), bytes.size(), state).ok);
  lcmtf_test::expectEqual(state, names_only);

  tf_message_t batch;
  const std::vector<std::uint8_t> three = encode(lcmtf_test::sampleTfMessage(3));
  ASSERT_TRUE(decodeMessage(three.data(), three.size(), batch).ok);
  const std::vector<std::uint8_t> none = encode(lcmtf_test::sampleTfMessage(0));
  ASSERT_TRUE(decodeMessage(none.data(), none.size(), batch).ok);
  EXPECT_TRUE(batch.transforms.empty());
}

TEST(WireDecode, AReusedMessageHoldsExactlyTheNewOne) {
  tf_message_t batch;
  tf_message_t long_names = lcmtf_test::sampleTfMessage(3);
  for (transform_t& t : long_names.transforms) {
    t.parent_frame += "_with_a_name_longer_than_the_next_one";
    t.child_frame += "_with_a_name_longer_than_the_next_one";
  }
  const std::vector<std::uint8_t> three = encode(long_names);
  ASSERT_TRUE(decodeMessage(three.data(), three.size(), batch).ok);
  tf_message_t two = lcmtf_test::sampleTfMessage(2);
  two.authority = "a";
  const std::vector<std::uint8_t> bytes = encode(two);
  ASSERT_TRUE(decodeMessage(bytes.data(), bytes.size(), batch).ok);
  lcmtf_test::expectEqual(batch, two);

  joint_state_t state;
  const std::vector<std::uint8_t> full = encode(lcmtf_test::sampleJointState());
  ASSERT_TRUE(decodeMessage(full.data(), full.size(), state).ok);
  joint_state_t fewer = lcmtf_test::sampleJointState();
  fewer.name = {"knee"};
  fewer.num_joints = 1;
  fewer.position = {2.0};
  fewer.num_positions = 1;
  fewer.velocity.clear();
  fewer.num_velocities = 0;
  const std::vector<std::uint8_t> fewer_bytes = encode(fewer);
  ASSERT_TRUE(decodeMessage(fewer_bytes.data(), fewer_bytes.size(), state).ok);
  lcmtf_test::expectEqual(state, fewer);
}

// Random bytes behind a valid fingerprint, and random corruptions of valid messages: decoding
// either succeeds, as LCM's generated decode would, or fails with a reason; it never crashes,
// hangs or allocates wildly.
TEST(WireDecode, GarbageNeverCrashes) {
  std::mt19937 random(1234);
  const std::vector<std::uint8_t> valid = encode(lcmtf_test::sampleTfMessage(4));
  std::size_t accepted = 0;
  tf_message_t out;  // reused, as a listener reuses it
  for (int round = 0; round < 20000; ++round) {
    std::vector<std::uint8_t> bytes = valid;
    if (round % 2 == 0) {
      bytes.resize(8 + random() % 400);
      for (std::size_t i = 8; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(random());
    } else {
      for (int flips = 1 + static_cast<int>(random() % 4); flips > 0; --flips) {
        bytes[8 + random() % (bytes.size() - 8)] = static_cast<std::uint8_t>(random());
      }
    }
    const DecodeResult result = decodeMessage(bytes.data(), bytes.size(), out);
    if (result.ok) {
      ++accepted;
      EXPECT_EQ(out.num_transforms, static_cast<std::int32_t>(out.transforms.size()));
      // What LCM's generated decode makes of the same bytes, and the bytes themselves again.
      tf_message_t theirs;
      ASSERT_EQ(theirs.decode(bytes.data(), 0, static_cast<int>(bytes.size())),
                static_cast<int>(bytes.size()));
      EXPECT_EQ(encode(out), bytes);
      EXPECT_EQ(encode(theirs), bytes);
    } else {
      EXPECT_FALSE(result.error.empty());
    }
  }
  EXPECT_GT(accepted, 0u) << "corrupted doubles alone should still decode";
}

}  // namespace
}  // namespace lcmtf
