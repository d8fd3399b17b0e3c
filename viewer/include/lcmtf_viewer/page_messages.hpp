#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace lcmtf::viewer {

/// The page drew the scene numbered `seq`.
struct AckMessage {
  std::int64_t seq = 0;
};

/// The page wants the scene in `fixed_frame`, live or paused at a stamp (microseconds).
struct ViewMessage {
  std::string fixed_frame;
  std::optional<std::int64_t> time_us;
};

/// The page's joint sliders: publish these positions while enabled.
struct JointsMessage {
  bool enabled = false;
  std::map<std::string, double> positions;
};

/// A message the page may send.
using PageMessage = std::variant<AckMessage, ViewMessage, JointsMessage>;

/// Limits on what a page may send.
inline constexpr std::size_t kMaxPageMessageBytes = 64 * 1024;
inline constexpr std::size_t kMaxNesting = 8;
inline constexpr std::size_t kMaxFrameNameBytes = 1024;
inline constexpr std::size_t kMaxJointPositions = 1000;

/// The message in `text`, or why it is refused ("view.fixed_frame: not a string").
std::variant<PageMessage, std::string> parsePageMessage(std::string_view text);

}  // namespace lcmtf::viewer
