// libFuzzer target: bytes from the network into a listener and its buffer, then every kind of
// query on whatever got in. Any crash, sanitizer report or escaped exception is a bug.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "fuzz_check.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lookup_mode.hpp"

namespace {

void queryEverything(const lcmtf::Buffer& buffer) {
  const std::vector<std::string> frames = buffer.getAllFrameNames();
  const std::size_t limit = std::min<std::size_t>(frames.size(), 12);
  for (std::size_t a = 0; a < limit; ++a) {
    for (std::size_t b = 0; b < limit; ++b) {
      std::string why;
      for (const lcmtf::TimePoint time : {lcmtf::kLatestTime, lcmtf::fromUtime(1'000'000)}) {
        buffer.canTransform(frames[a], frames[b], time, &why);
        try {
          buffer.lookupTransform(frames[a], frames[b], time);
          buffer.getFrameChain(frames[a], frames[b], time);
        } catch (const lcmtf::TransformException&) {
        }
      }
      try {
        buffer.lookupVelocity(frames[a], frames[b], lcmtf::kLatestTime,
                              std::chrono::milliseconds(100));
      } catch (const lcmtf::TransformException&) {
      }
    }
  }
  buffer.allFramesAsYaml();
  buffer.allFramesAsDot();
}

// lcmtf reads a tf_message_t itself, in one pass with its checks: what it accepts must be what
// LCM's generated decode makes of the same bytes, and encode back to them.
void checkDecodeAgreesWithLcm(const std::uint8_t* data, std::size_t size) {
  lcmtf::tf_message_t ours;
  if (!lcmtf::decodeMessage(data, size, ours).ok) return;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  lcmtf::tf_message_t theirs;
  if (theirs.decode(data, 0, static_cast<int>(size)) != static_cast<int>(size)) {
    lcmtf_fuzz::fail("accepted bytes LCM's decode refuses", bytes);
  }
  std::vector<std::uint8_t> again(size);
  if (ours.getEncodedSize() != static_cast<int>(size) ||
      ours.encode(again.data(), 0, static_cast<int>(size)) != static_cast<int>(size) ||
      std::memcmp(again.data(), data, size) != 0) {
    lcmtf_fuzz::fail("decoded bytes that do not encode back to themselves", bytes);
  }
  std::vector<std::uint8_t> theirs_again(size);
  theirs.encode(theirs_again.data(), 0, static_cast<int>(size));
  if (theirs_again != again) lcmtf_fuzz::fail("decoded otherwise than LCM's decode", bytes);
}

}  // namespace

// Quick lookups are not checked against the walk here: the fuzzer's absurd magnitudes (1e300
// metres) probe rounding, where two orders of composition may differ, not the path logic.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  lcmtf::detail::setCrossCheckEnabled(false);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static lcm::LCM lcm("memq://");
  if (size < 1) return 0;
  // The first byte says how many messages the rest holds and which channels they came on.
  const std::size_t messages = 1 + (data[0] & 3);
  const std::size_t chunk = (size - 1) / messages;
  lcmtf::Buffer buffer(std::chrono::seconds(1));
  buffer.setErrorReporter(nullptr);
  lcmtf::ListenerOptions options;
  options.max_frames = 64;
  options.reporter = nullptr;
  lcmtf::TransformListener listener(buffer, lcm, options);
  for (std::size_t i = 0; i < messages; ++i) {
    const std::uint8_t* message = data + 1 + i * chunk;
    const std::size_t length = i + 1 == messages ? size - 1 - i * chunk : chunk;
    checkDecodeAgreesWithLcm(message, length);
    listener.handleMessage(message, length, (data[0] >> (2 + i)) & 1 ? "TF_STATIC" : "TF");
    lcmtf::joint_state_t joints;
    lcmtf::decodeMessage(message, length, joints);
    lcmtf::robot_description_t description;
    lcmtf::decodeMessage(message, length, description);
  }
  queryEverything(buffer);
  return 0;
}
