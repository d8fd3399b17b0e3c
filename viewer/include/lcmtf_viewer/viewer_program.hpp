#pragma once

#include <atomic>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "lcmtf/channels.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf/transform_listener.hpp"

namespace lcmtf::viewer {

/// Everything lcmtf-viewer's command line sets.
struct ViewerOptions {
  std::string bind_address = "127.0.0.1";
  int port = 8080;
  std::vector<std::string> allowed_hosts;
  std::vector<std::string> allowed_origins;
  std::string lcm_url;
  std::string tf_channel = kTfChannel;
  std::string static_channel = kTfStaticChannel;
  std::string request_channel = kTfStaticRequestChannel;
  std::string description_channel = kRobotDescriptionChannel;
  std::string description_request_channel = kRobotDescriptionRequestChannel;
  std::string joint_states_channel = kJointStatesChannel;
  std::string urdf_path;
  std::vector<std::string> package_paths;
  std::string fixed_frame;
  double update_hz = 30.0;
  double stale_after_s = 1.0;
  double cache_time_s = 10.0;
  double max_stamp_ahead_s = toSeconds(kDefaultMaxStampAhead);
  std::string web_root;  ///< "" finds the page beside the program
  std::string three_dir;
  double duration_s = 0.0;  ///< 0: until stopped
};

/// Reads the command line into `options`; the exit status when the program must not run.
std::optional<int> parseViewerCommandLine(const std::vector<std::string>& args,
                                          ViewerOptions& options, std::ostream& out,
                                          std::ostream& err);

/// Serves the viewer until `stop` is set; returns the exit status.
int runViewer(const ViewerOptions& options, std::ostream& out, std::ostream& err,
              const std::atomic<bool>& stop);

/// The whole program.
int viewerMain(int argc, char** argv);

}  // namespace lcmtf::viewer
