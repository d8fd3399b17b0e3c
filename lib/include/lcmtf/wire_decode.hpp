#pragma once

#include <cstddef>
#include <string>

#include "lcmtf/joint_state_t.hpp"
#include "lcmtf/resend_request_t.hpp"
#include "lcmtf/robot_description_t.hpp"
#include "lcmtf/tf_message_t.hpp"
#include "lcmtf/transform_t.hpp"

namespace lcmtf {

/// Bounds a decoded message must respect; bytes that claim more are rejected before any allocation.
struct DecodeLimits {
  std::size_t max_name_bytes = 256;        ///< frame, joint, authority and robot names
  std::size_t max_array_elements = 65536;  ///< transforms in a batch, joints in a state
};

/// The outcome of a decode: ok, or what was wrong with the bytes, naming the field.
struct DecodeResult {
  bool ok = false;
  std::string error;
  explicit operator bool() const { return ok; }
};

/// Decodes LCM bytes into `out` without trusting any length or count they carry: a wrong
/// fingerprint, truncation, a bad string or an absurd count fails with a reason instead.
/// Defined for transform_t, tf_message_t, joint_state_t, resend_request_t, robot_description_t.
/// `out` may be reused from one message to the next: it then holds exactly the new message,
/// with no allocation where its strings and arrays already have room. After a failure it holds
/// whatever was read before the fault.
template <class Message>
DecodeResult decodeMessage(const void* data, std::size_t size, Message& out,
                           const DecodeLimits& limits = {});

}  // namespace lcmtf
