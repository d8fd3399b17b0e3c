#pragma once

#include <atomic>
#include <ostream>
#include <string>
#include <vector>

#include "lcmtf_urdf/command_line.hpp"
#include "lcmtf_urdf/urdf_publisher.hpp"

namespace lcmtf::urdf {

/// What lcmtf-urdf-publisher is asked to do.
struct UrdfPublisherConfig {
  std::string urdf_path;  ///< empty: wait for the robot on the description channel
  std::string lcm_url;    ///< "" is LCM's default (udpm://239.255.76.67:7667?ttl=0)
  UrdfPublisherOptions publisher;
  bool check_only = false;  ///< read and check the URDF, say what would be published, exit
};

/// lcmtf-urdf-publisher's command line (without the program name).
ParsedCommandLine<UrdfPublisherConfig> parseUrdfPublisherCommandLine(
    const std::vector<std::string>& arguments);

/// Runs the publisher until `stop` is set; 0 when stopped, 1 (with the reason on `err`) when
/// the robot or LCM cannot be used.
int runUrdfPublisher(const UrdfPublisherConfig& config, const std::atomic<bool>& stop,
                     std::ostream& out, std::ostream& err);

/// The whole program: command line, SIGINT/SIGTERM, run.
int urdfPublisherMain(int argc, char** argv);

}  // namespace lcmtf::urdf
