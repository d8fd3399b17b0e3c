#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lcmtf::viewer {

/// Which Host and Origin headers the server answers. A browser can be made to send requests
/// here by any web page: through the WebSocket, which no same-origin rule guards, or under a
/// name of the page's own rebound to this machine's address. Both are refused, so that only
/// pages served by this viewer, under a name of this machine, see the robot and move its joints.
class HostPolicy {
 public:
  /// `allowed_hosts`: names besides IP addresses, localhost and this machine's name ("*": any).
  /// `allowed_origins`: other pages, as scheme://host[:port], that may open the WebSocket.
  HostPolicy(std::vector<std::string> allowed_hosts, std::vector<std::string> allowed_origins);

  /// Why a request with this Host header is not answered; nothing when it is.
  std::optional<std::string> refuseHost(std::string_view host) const;
  /// Why a page at `origin` may not open the WebSocket of a request to `host`; nothing when it
  /// may. A request without an Origin (`origin` empty) is not from a browser and may.
  std::optional<std::string> refuseOrigin(std::string_view origin, std::string_view host) const;

 private:
  bool isOwnName(const std::string& name) const;

  std::vector<std::string> allowed_hosts_;
  std::vector<std::string> allowed_origins_;
  std::string machine_name_;
};

}  // namespace lcmtf::viewer
