#include "command_line_helpers.hpp"

#include "lcmtf/programs/lcm_connection.hpp"

namespace lcmtf::urdf {

void addRobotSourceOptions(CLI::App& app, const RobotSourceArguments& arguments) {
  app.add_option("urdf", arguments.urdf_path,
                 "The robot's URDF file; without it, the first valid description on "
                 "--description-channel is used")
      ->type_name("URDF");
  app.add_option("--lcm-url", arguments.lcm_url,
                 "LCM URL to talk on (default: $LCM_DEFAULT_URL, else " +
                     std::string(programs::lcmBuiltInDefaultUrl()) + ")")
      ->type_name("URL");
  programs::addChannelOption(app, "--description-channel", arguments.description_channel,
                             "Channel of the robot's URDF text");
  programs::addChannelOption(app, "--description-request-channel",
                             arguments.description_request_channel,
                             "Channel on which the URDF text is asked for");
  arguments.authority = programs::programAuthority(app.get_name());
  app.add_option("--authority", arguments.authority,
                 "Names this program in what it sends (default: program@host:pid)")
      ->check(programs::sendableName())
      ->type_name("NAME");
}

}  // namespace lcmtf::urdf
