#pragma once

#include <atomic>
#include <ostream>
#include <string>
#include <vector>

#include "lcmtf/channels.hpp"
#include "lcmtf_urdf/command_line.hpp"
#include "lcmtf_urdf/joint_state_generator.hpp"

namespace lcmtf::urdf {

/// What lcmtf-joint-publisher is asked to do.
struct JointPublisherConfig {
  std::string urdf_path;  ///< empty: wait for the robot on the description channel
  std::string lcm_url;    ///< "" is LCM's default
  std::string channel = kJointStatesChannel;
  std::string description_channel = kRobotDescriptionChannel;
  std::string description_request_channel = kRobotDescriptionRequestChannel;
  std::string authority = defaultAuthority();  ///< signs its joint states and description requests
  double rate = 50.0;                          ///< joint states per second
  double duration = 0.0;                       ///< seconds to run; 0 runs until stopped
  JointStateGeneratorOptions generator;
  /// Channels of joint states whose positions take the place of the generated ones (as
  /// joint_state_publisher's source_list).
  std::vector<std::string> sources;
};

/// lcmtf-joint-publisher's command line (without the program name).
ParsedCommandLine<JointPublisherConfig> parseJointPublisherCommandLine(
    const std::vector<std::string>& arguments);

/// Publishes joint states at config.rate until `stop` is set or the duration is over: 0 then,
/// 1 (with the reason on `err`) when the robot, a held joint or LCM cannot be used.
int runJointPublisher(const JointPublisherConfig& config, const std::atomic<bool>& stop,
                      std::ostream& out, std::ostream& err);

/// The whole program: command line, SIGINT/SIGTERM, run.
int jointPublisherMain(int argc, char** argv);

}  // namespace lcmtf::urdf
