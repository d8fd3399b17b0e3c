#include "lcmtf/wire_decode.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <initializer_list>
#include <limits>
#include <string>
#include <type_traits>

namespace lcmtf {
namespace {

constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();
constexpr std::size_t kVector3Bytes = 3 * 8;
constexpr std::size_t kQuaternionBytes = 4 * 8;
constexpr std::size_t kShortestString = 4 + 1;
constexpr std::size_t kShortestTransform =
    8 + 2 * kShortestString + kVector3Bytes + kQuaternionBytes;

// Walks LCM's encoding of a message, checking every length and count against the bytes that
// are really there and against the limits: reading the fields of the types a listener
// receives as it goes, skipping those of the others (LCM's decode builds them once checked).
class WireReader {
 public:
  WireReader(const std::uint8_t* data, std::size_t size, const DecodeLimits& limits)
      : data_(data), size_(size), limits_(limits) {}

  const std::string& error() const { return error_; }
  std::size_t remaining() const { return size_ - position_; }
  const DecodeLimits& limits() const { return limits_; }

  void enterElement(const char* array, std::size_t index) {
    array_ = array;
    index_ = index;
  }
  void leaveElement() { array_ = nullptr; }

  bool fail(const char* field, const std::string& what) {
    if (error_.empty()) {
      error_ = array_ ? std::string(array_) + "[" + std::to_string(index_) + "]." : std::string();
      error_ += std::string(field) + ": " + what;
    }
    return false;
  }

  bool skip(std::size_t bytes, const char* field) {
    if (bytes > remaining()) {
      return fail(field, "truncated: needs " + std::to_string(bytes) + " bytes, " +
                             std::to_string(remaining()) + " remain");
    }
    position_ += bytes;
    return true;
  }

  bool readInt32(std::int32_t& value, const char* field) {
    if (remaining() < 4) return skip(4, field);
    const std::uint8_t* p = data_ + position_;
    value = static_cast<std::int32_t>((std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) |
                                      (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]});
    position_ += 4;
    return true;
  }

  bool readInt64(std::int64_t& value, const char* field) {
    if (remaining() < 8) return skip(8, field);
    value = static_cast<std::int64_t>(bigEndianWordAt(position_));
    position_ += 8;
    return true;
  }

  // The doubles of one field (a vector or a quaternion), checked for room at once.
  bool readDoubles(std::initializer_list<double*> values, const char* field) {
    if (remaining() < 8 * values.size()) return skip(8 * values.size(), field);
    for (double* value : values) {
      const std::uint64_t bits = bigEndianWordAt(position_);
      std::memcpy(value, &bits, sizeof bits);
      position_ += 8;
    }
    return true;
  }

  bool skipString(const char* field, std::size_t max_bytes) {
    std::size_t length = 0;
    return checkedString(field, max_bytes, length) != nullptr;
  }

  bool skipName(const char* field) { return skipString(field, limits_.max_name_bytes); }

  bool readName(std::string& out, const char* field) {
    std::size_t length = 0;
    const char* text = checkedString(field, limits_.max_name_bytes, length);
    if (text == nullptr) return false;
    out.assign(text, length);
    return true;
  }

  // Reads an array length and checks that the bytes left could hold that many elements.
  bool readCount(std::int32_t& count, const char* field, std::size_t shortest_element_bytes) {
    if (!readInt32(count, field)) return false;
    if (count < 0) return fail(field, "negative count " + std::to_string(count));
    const auto elements = static_cast<std::size_t>(count);
    if (elements > limits_.max_array_elements) {
      return fail(field, "count " + std::to_string(count) + " exceeds the limit of " +
                             std::to_string(limits_.max_array_elements));
    }
    if (elements > remaining() / shortest_element_bytes) {
      return fail(field, "truncated: count " + std::to_string(count) + " needs at least " +
                             std::to_string(elements * shortest_element_bytes) + " bytes, " +
                             std::to_string(remaining()) + " remain");
    }
    return true;
  }

 private:
  std::uint64_t bigEndianWordAt(std::size_t at) const {
    std::uint64_t bits = 0;
    std::memcpy(&bits, data_ + at, sizeof bits);
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    bits = __builtin_bswap64(bits);
#endif
    return bits;
  }

  // The text of a string field (its length in `length`), moved past; null when the field is
  // not a string of at most `max_bytes` bytes, NUL-terminated, with no other NUL in it.
  const char* checkedString(const char* field, std::size_t max_bytes, std::size_t& length) {
    std::int32_t length_with_nul = 0;
    if (!readInt32(length_with_nul, field)) return nullptr;
    if (length_with_nul < 1) {
      fail(field, "string length field is " + std::to_string(length_with_nul) +
                      " (at least 1 for the terminating NUL)");
      return nullptr;
    }
    length = static_cast<std::size_t>(length_with_nul) - 1;
    if (length > max_bytes) {
      fail(field, "string of " + std::to_string(length) + " bytes exceeds the limit of " +
                      std::to_string(max_bytes) + " bytes");
      return nullptr;
    }
    if (static_cast<std::size_t>(length_with_nul) > remaining()) {
      skip(static_cast<std::size_t>(length_with_nul), field);
      return nullptr;
    }
    const auto* text = reinterpret_cast<const char*>(data_ + position_);
    if (text[length] != 0) {
      fail(field, "string is not NUL-terminated");
      return nullptr;
    }
    if (std::memchr(text, 0, length) != nullptr) {
      fail(field, "string contains a NUL byte");
      return nullptr;
    }
    position_ += static_cast<std::size_t>(length_with_nul);
    return text;
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
  const DecodeLimits& limits_;
  std::string error_;
  const char* array_ = nullptr;
  std::size_t index_ = 0;
};

// The types a listener receives are read as they are checked, in one pass: twice as fast as
// checking, then decoding with LCM's generated code, which reads a double a byte at a time.
bool readBody(WireReader& wire, transform_t& t) {
  return wire.readInt64(t.utime, "utime") && wire.readName(t.parent_frame, "parent_frame") &&
         wire.readName(t.child_frame, "child_frame") &&
         wire.readDoubles({&t.translation.x, &t.translation.y, &t.translation.z}, "translation") &&
         wire.readDoubles({&t.rotation.x, &t.rotation.y, &t.rotation.z, &t.rotation.w}, "rotation");
}

bool readBody(WireReader& wire, tf_message_t& message) {
  std::int32_t count = 0;
  if (!(wire.readInt64(message.utime, "utime") && wire.readName(message.authority, "authority") &&
        wire.readInt64(message.sequence, "sequence") &&
        wire.readCount(count, "num_transforms", kShortestTransform))) {
    return false;
  }
  message.num_transforms = count;
  // Reused elements keep their strings' room for the names read into them.
  message.transforms.resize(static_cast<std::size_t>(count));
  for (std::int32_t i = 0; i < count; ++i) {
    wire.enterElement("transforms", static_cast<std::size_t>(i));
    if (!readBody(wire, message.transforms[static_cast<std::size_t>(i)])) return false;
  }
  wire.leaveElement();
  return true;
}

bool skimDoubles(WireReader& wire, const char* count_field, const char* values_field) {
  std::int32_t count = 0;
  return wire.readCount(count, count_field, 8) &&
         wire.skip(static_cast<std::size_t>(count) * 8, values_field);
}

bool skimBody(WireReader& wire, const joint_state_t*) {
  std::int32_t joints = 0;
  if (!(wire.skip(8, "utime") && wire.skipName("authority") && wire.skip(8, "sequence") &&
        wire.readCount(joints, "num_joints", kShortestString))) {
    return false;
  }
  for (std::int32_t i = 0; i < joints; ++i) {
    wire.enterElement("name", static_cast<std::size_t>(i));
    if (!wire.skipName("name")) return false;
  }
  wire.leaveElement();
  return skimDoubles(wire, "num_positions", "position") &&
         skimDoubles(wire, "num_velocities", "velocity") &&
         skimDoubles(wire, "num_efforts", "effort");
}

bool skimBody(WireReader& wire, const resend_request_t*) {
  return wire.skip(8, "utime") && wire.skipName("requester");
}

bool skimBody(WireReader& wire, const robot_description_t*) {
  return wire.skip(8, "utime") && wire.skipName("authority") && wire.skipName("robot_name") &&
         wire.skipString("urdf", kUnbounded);
}

// LCM's generated decode resizes an array only when its count is non-zero, so decoding into a
// reused message would keep the previous message's elements wherever this one has none. Sized
// after the decode rather than emptied before it, a reused message keeps its elements' strings,
// whose room the next message's names then fill without allocating.
void sizeArrays(joint_state_t& message) {
  message.name.resize(static_cast<std::size_t>(message.num_joints));
  message.position.resize(static_cast<std::size_t>(message.num_positions));
  message.velocity.resize(static_cast<std::size_t>(message.num_velocities));
  message.effort.resize(static_cast<std::size_t>(message.num_efforts));
}
void sizeArrays(resend_request_t&) {}
void sizeArrays(robot_description_t&) {}

std::string hex(std::int64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016llx",
                static_cast<unsigned long long>(static_cast<std::uint64_t>(value)));
  return text;
}

}  // namespace

template <class Message>
DecodeResult decodeMessage(const void* data, std::size_t size, Message& out,
                           const DecodeLimits& limits) {
  const std::string type = Message::getTypeName();
  DecodeResult result;
  if (data == nullptr && size > 0) {
    result.error = type + ": no data";
    return result;
  }
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    result.error = type + ": " + std::to_string(size) + " bytes is larger than LCM can encode";
    return result;
  }
  WireReader wire(static_cast<const std::uint8_t*>(data), size, limits);
  std::int64_t fingerprint = 0;
  if (!wire.readInt64(fingerprint, "fingerprint")) {
    result.error = type + ": " + wire.error();
    return result;
  }
  if (fingerprint != Message::getHash()) {
    result.error = type + ": fingerprint " + hex(fingerprint) + " is not " + type + "'s " +
                   hex(Message::getHash()) + " (another type, or another version of it)";
    return result;
  }
  constexpr bool kRead =
      std::is_same_v<Message, tf_message_t> || std::is_same_v<Message, transform_t>;
  bool body_ok = false;
  if constexpr (kRead) {
    body_ok = readBody(wire, out);
  } else {
    body_ok = skimBody(wire, &out);
  }
  if (!body_ok) {
    result.error = type + ": " + wire.error();
    return result;
  }
  if (wire.remaining() != 0) {
    result.error = type + ": " + std::to_string(wire.remaining()) +
                   " unexpected bytes after the end of the message";
    return result;
  }
  if constexpr (!kRead) {
    try {
      const int decoded = out.decode(data, 0, static_cast<int>(size));
      if (decoded != static_cast<int>(size)) {
        result.error = type + ": LCM decode failed (returned " + std::to_string(decoded) + ")";
        return result;
      }
      sizeArrays(out);
    } catch (const std::exception& e) {
      result.error = type + ": LCM decode failed: " + e.what();
      return result;
    }
  }
  result.ok = true;
  return result;
}

template DecodeResult decodeMessage(const void*, std::size_t, tf_message_t&, const DecodeLimits&);
template DecodeResult decodeMessage(const void*, std::size_t, transform_t&, const DecodeLimits&);
template DecodeResult decodeMessage(const void*, std::size_t, joint_state_t&, const DecodeLimits&);
template DecodeResult decodeMessage(const void*, std::size_t, resend_request_t&,
                                    const DecodeLimits&);
template DecodeResult decodeMessage(const void*, std::size_t, robot_description_t&,
                                    const DecodeLimits&);

}  // namespace lcmtf
