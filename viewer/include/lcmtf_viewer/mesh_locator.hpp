#pragma once

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace lcmtf::viewer {

/// Where the mesh files a robot description names are looked for.
struct MeshSearch {
  /// Folders holding packages: "package://name/x" is <folder>/name/x, or <folder>/x when the
  /// folder itself is named "name". --package-path folders first, then ROS_PACKAGE_PATH's.
  std::vector<std::filesystem::path> package_paths;
  /// The folder of the URDF file, for relative file names; empty for a description heard on
  /// LCM, whose relative names mean nothing here.
  std::filesystem::path description_folder;
};

/// The folders of `ros_package_path` ("a:b:c"; empty entries skipped).
std::vector<std::filesystem::path> splitPackagePath(const std::string& ros_package_path);

/// Finds the file a URDF mesh filename names: package://, file:// or a plain path. The result
/// is a regular file inside a package path or the description's folder (a ".." or a symbolic
/// link leading out is refused), or why it was not found.
std::variant<std::filesystem::path, std::string> locateMesh(const std::string& filename,
                                                            const MeshSearch& search);

}  // namespace lcmtf::viewer
