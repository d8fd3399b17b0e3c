#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lcmtf_urdf/robot_model.hpp"
#include "lcmtf_viewer/mesh_locator.hpp"

namespace lcmtf::viewer {

/// A robot as the page draws it: the `robot` message of the protocol, and the mesh files its
/// URLs stand for ("/mesh/<index>/<name>").
struct RobotView {
  nlohmann::json robot;  ///< the value of the message's "robot" field
  std::vector<std::filesystem::path> meshes;
  std::vector<std::string> warnings;  ///< also in robot["warnings"]
};

/// The view of `model` (already checked), its visuals read from its URDF text, its meshes
/// looked for as `search` says. A visual that cannot be drawn is left out with a warning.
RobotView makeRobotView(const urdf::RobotModel& model, const MeshSearch& search);

/// The URL path of the index-th mesh, named after `file` with characters outside
/// [A-Za-z0-9._-] replaced.
std::string meshUrlPath(std::size_t index, const std::filesystem::path& file);

}  // namespace lcmtf::viewer
