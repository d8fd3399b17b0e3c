#include "lcmtf/nodes/tf_connection.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <ostream>

#include "lcmtf/nodes/command_line.hpp"

namespace lcmtf::nodes {

namespace {

constexpr const char* kLcmBuiltInDefaultUrl = "udpm://239.255.76.67:7667?ttl=0";

}  // namespace

void addConnectionOptions(CLI::App& app, TfConnection& connection, bool with_dynamic) {
  app.add_option("--lcm-url", connection.lcm_url,
                 "LCM URL to talk on (default: $LCM_DEFAULT_URL, else " +
                     std::string(kLcmBuiltInDefaultUrl) + ")")
      ->type_name("URL");
  if (with_dynamic) {
    app.add_option("--tf-channel", connection.tf_channel, "Channel of dynamic transforms")
        ->capture_default_str()
        ->check(nonEmptyName())
        ->type_name("NAME");
  }
  app.add_option("--static-channel", connection.static_channel, "Channel of static transforms")
      ->capture_default_str()
      ->check(nonEmptyName())
      ->type_name("NAME");
  app.add_option("--request-channel", connection.request_channel,
                 "Channel on which static transforms are asked for again")
      ->capture_default_str()
      ->check(nonEmptyName())
      ->type_name("NAME");
}

std::string describeLcmUrl(const std::string& lcm_url) {
  if (!lcm_url.empty()) return lcm_url;
  const char* from_environment = std::getenv("LCM_DEFAULT_URL");
  if (from_environment && *from_environment) return from_environment;
  return kLcmBuiltInDefaultUrl;
}

std::unique_ptr<lcm::LCM> openLcm(const TfConnection& connection) {
  auto lcm = std::make_unique<lcm::LCM>(connection.lcm_url);
  if (!lcm->good()) {
    throw CommandLineError("--lcm-url: cannot open LCM at '" + describeLcmUrl(connection.lcm_url) +
                           "'");
  }
  return lcm;
}

std::unique_ptr<lcm::LCM> openLcmOrReport(const TfConnection& connection,
                                          const std::string& program, std::ostream& err) {
  try {
    return openLcm(connection);
  } catch (const CommandLineError& e) {
    err << program << ": " << e.what() << std::endl;
    return nullptr;
  }
}

bool handleLcmFor(lcm::LCM& lcm, std::chrono::milliseconds timeout, bool* handled) {
  const int milliseconds = static_cast<int>(std::clamp<std::int64_t>(timeout.count(), 0, 1000));
  errno = 0;
  const int result = lcm.handleTimeout(milliseconds);
  if (handled) *handled = result > 0;
  return result >= 0 || errno == EINTR;
}

ListenerOptions listenerOptionsFor(const TfConnection& connection, const std::string& program) {
  ListenerOptions listener;
  listener.channel = connection.tf_channel;
  listener.static_channel = connection.static_channel;
  listener.static_request_channel = connection.request_channel;
  listener.authority = toolAuthority(program);
  listener.reporter = nullptr;
  return listener;
}

}  // namespace lcmtf::nodes
