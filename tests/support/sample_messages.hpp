#pragma once

#include <gtest/gtest.h>

#include "lcmtf/joint_state_t.hpp"
#include "lcmtf/resend_request_t.hpp"
#include "lcmtf/robot_description_t.hpp"
#include "lcmtf/tf_message_t.hpp"
#include "lcmtf/transform_t.hpp"

namespace lcmtf_test {

/// Messages whose every field holds a distinct, non-default value, so a field lost or
/// swapped on the way shows up.
lcmtf::transform_t sampleTransform(int seed = 0);
lcmtf::tf_message_t sampleTfMessage(int transforms = 3);
lcmtf::joint_state_t sampleJointState();
lcmtf::resend_request_t sampleResendRequest();
lcmtf::robot_description_t sampleRobotDescription();

/// Field-by-field equality, each mismatch reported with the field's name.
void expectEqual(const lcmtf::transform_t& actual, const lcmtf::transform_t& expected);
void expectEqual(const lcmtf::tf_message_t& actual, const lcmtf::tf_message_t& expected);
void expectEqual(const lcmtf::joint_state_t& actual, const lcmtf::joint_state_t& expected);
void expectEqual(const lcmtf::resend_request_t& actual, const lcmtf::resend_request_t& expected);
void expectEqual(const lcmtf::robot_description_t& actual,
                 const lcmtf::robot_description_t& expected);

/// The LCM encoding of a message, fingerprint first.
template <class Message>
std::vector<std::uint8_t> encode(const Message& message) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace lcmtf_test
