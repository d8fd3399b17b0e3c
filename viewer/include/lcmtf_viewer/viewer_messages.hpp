#pragma once

#include <map>
#include <string>

#include "lcmtf/time.hpp"
#include "lcmtf_viewer/robot_view.hpp"
#include "lcmtf_viewer/scene_snapshot.hpp"

namespace lcmtf::viewer {

/// What the server tells a page first.
struct HelloFacts {
  std::string version;
  std::string fixed_frame;  ///< the server's suggestion; "" when it has none yet
  double update_hz = 30.0;
  std::string joint_states_channel;
};

/// The protocol's server-to-page messages (see viewer/protocol.md), as JSON text.
std::string helloMessage(const HelloFacts& facts);
/// The "robot" message; `robot` null when none is loaded.
std::string robotMessage(const RobotView* robot);
/// The "tree" message: every edge with its sender, rate, age and staleness at forest.now.
std::string treeMessage(const FrameForest& forest, Duration stale_after);
std::string jointsMessage(bool publishing, const std::map<std::string, double>& positions);
std::string errorMessage(const std::string& text);

}  // namespace lcmtf::viewer
