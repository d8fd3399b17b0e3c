#include "lcmtf/nodes/tf_connection.hpp"

namespace lcmtf::nodes {

void addConnectionOptions(CLI::App& app, TfConnection& connection, bool with_dynamic) {
  app.add_option("--lcm-url", connection.lcm_url,
                 "LCM URL to talk on (default: $LCM_DEFAULT_URL, else " +
                     std::string(lcmBuiltInDefaultUrl()) + ")")
      ->type_name("URL");
  if (with_dynamic) {
    addChannelOption(app, "--tf-channel", connection.tf_channel, "Channel of dynamic transforms");
  }
  addChannelOption(app, "--static-channel", connection.static_channel,
                   "Channel of static transforms");
  addChannelOption(app, "--request-channel", connection.request_channel,
                   "Channel on which static transforms are asked for again");
}

ListenerOptions listenerOptionsFor(const TfConnection& connection, const std::string& program) {
  ListenerOptions listener;
  listener.max_stamp_ahead = secondsToDuration(connection.max_stamp_ahead_s);
  listener.channel = connection.tf_channel;
  listener.static_channel = connection.static_channel;
  listener.static_request_channel = connection.request_channel;
  listener.authority = programAuthority(program);
  listener.reporter = nullptr;
  return listener;
}

}  // namespace lcmtf::nodes
