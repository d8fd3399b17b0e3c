// libFuzzer target: what a page or a browser sends lcmtf-viewer from the network, the WebSocket
// text through the page-message parser, the Host and Origin headers through the host policy.
// Any crash, sanitizer report or escaped exception is a bug; so is a message let through beyond
// the limits, a refusal that echoes more than a short slice of what was sent, or one that the
// error message to the page cannot carry as JSON.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "fuzz_check.hpp"
#include "lcmtf_viewer/host_policy.hpp"
#include "lcmtf_viewer/page_messages.hpp"
#include "lcmtf_viewer/viewer_messages.hpp"

namespace {

using lcmtf::viewer::PageMessage;
using lcmtf_fuzz::fail;

// A refusal names the field and at most 64 bytes of a name or type the page sent.
constexpr std::size_t kLongestRefusal = 200;

void checkWithinLimits(const PageMessage& message) {
  if (const auto* view = std::get_if<lcmtf::viewer::ViewMessage>(&message)) {
    if (view->fixed_frame.size() > lcmtf::viewer::kMaxFrameNameBytes) {
      fail("a fixed frame longer than the limit got through", view->fixed_frame);
    }
    if (view->time_us && *view->time_us <= 0) fail("a view time <= 0 got through", "");
  } else if (const auto* joints = std::get_if<lcmtf::viewer::JointsMessage>(&message)) {
    if (joints->positions.size() > lcmtf::viewer::kMaxJointPositions) {
      fail("more joint positions than the limit got through", "");
    }
    for (const auto& [name, position] : joints->positions) {
      if (!std::isfinite(position)) fail("a position that is not finite got through", name);
    }
  } else if (std::get<lcmtf::viewer::AckMessage>(message).seq < 0) {
    fail("an ack of a negative scene got through", "");
  }
}

void checkRefusal(const std::string& why) {
  if (why.empty()) fail("a refusal without a reason", "");
  if (why.size() > kLongestRefusal) fail("a refusal echoes too much", why);
  const nlohmann::json sent =
      nlohmann::json::parse(lcmtf::viewer::errorMessage(why), nullptr, false);
  if (sent.is_discarded() || !sent.at("message").is_string()) {
    fail("the error message to the page is not JSON", why);
  }
}

void checkHeaders(std::string_view origin, std::string_view host) {
  static const lcmtf::viewer::HostPolicy policy({"robot.example"}, {"http://console.example:8080"});
  for (const auto& refusal : {policy.refuseHost(host), policy.refuseOrigin(origin, host)}) {
    if (refusal && refusal->empty()) fail("a header refused without a reason", "");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto parsed = lcmtf::viewer::parsePageMessage(text);
  if (const auto* message = std::get_if<PageMessage>(&parsed)) {
    checkWithinLimits(*message);
  } else {
    checkRefusal(std::get<std::string>(parsed));
  }
  // The same bytes as headers: an Origin up to the first newline, and a Host after it.
  const std::size_t newline = text.find('\n');
  if (newline == std::string_view::npos) {
    checkHeaders({}, text);
  } else {
    checkHeaders(text.substr(0, newline), text.substr(newline + 1));
  }
  return 0;
}
