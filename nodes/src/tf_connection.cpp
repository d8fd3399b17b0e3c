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

std::string stampedAheadNote(const TransformListener& listener, const TfConnection& connection) {
  const std::uint64_t refused = listener.statistics().stamped_ahead;
  if (refused == 0) return {};
  return std::to_string(refused) + " transform" + (refused == 1 ? " was" : "s were") +
         " refused as stamped more than " +
         toString(secondsToDuration(connection.max_stamp_ahead_s)) +
         " ahead of this machine's clock: synchronize the clocks, or take them with "
         "--max-stamp-ahead 0";
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
