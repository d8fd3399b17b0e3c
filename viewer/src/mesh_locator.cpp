#include "lcmtf_viewer/mesh_locator.hpp"

#include <optional>
#include <sstream>
#include <system_error>

namespace lcmtf::viewer {

namespace {

constexpr std::string_view kPackageScheme = "package://";
constexpr std::string_view kFileScheme = "file://";

bool startsWith(const std::string& text, std::string_view prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// `relative` under `folder`, as a regular file that stays inside the folder once links and
// ".." are resolved.
std::optional<std::filesystem::path> regularFileInside(const std::filesystem::path& folder,
                                                       const std::filesystem::path& relative) {
  std::error_code error;
  const std::filesystem::path real_folder = std::filesystem::canonical(folder, error);
  if (error) return std::nullopt;
  const std::filesystem::path real_file = std::filesystem::canonical(folder / relative, error);
  if (error || !std::filesystem::is_regular_file(real_file, error)) return std::nullopt;
  const std::filesystem::path inside = real_file.lexically_relative(real_folder);
  if (inside.empty() || *inside.begin() == "..") return std::nullopt;
  return real_file;
}

std::variant<std::filesystem::path, std::string> locatePackageFile(const std::string& filename,
                                                                   const MeshSearch& search) {
  const std::string rest = filename.substr(kPackageScheme.size());
  const std::size_t slash = rest.find('/');
  if (slash == std::string::npos || slash == 0) {
    return "'" + filename + "' names no file inside a package";
  }
  const std::string package = rest.substr(0, slash);
  if (package == "." || package == ".." || package.find('\\') != std::string::npos) {
    return "'" + filename + "': '" + package + "' is not a package name";
  }
  const std::filesystem::path relative = rest.substr(slash + 1);
  std::error_code error;
  for (const std::filesystem::path& folder : search.package_paths) {
    for (const std::filesystem::path& package_folder :
         {folder / package, folder.filename() == package ? folder : std::filesystem::path()}) {
      if (package_folder.empty() || !std::filesystem::is_directory(package_folder, error)) {
        continue;
      }
      if (auto found = regularFileInside(package_folder, relative)) return *found;
    }
  }
  if (search.package_paths.empty()) {
    return "'" + filename + "': no package paths to look in (give --package-path)";
  }
  std::ostringstream message;
  message << "'" << filename << "' not found in the package paths (";
  for (std::size_t i = 0; i < search.package_paths.size(); ++i) {
    message << (i ? ", " : "") << search.package_paths[i].string();
  }
  message << ")";
  return message.str();
}

// Only files inside a package path or the description's folder are served, so a description
// heard on the network cannot name any other file of this machine.
std::variant<std::filesystem::path, std::string> locateAbsoluteFile(
    const std::string& filename, const std::filesystem::path& path, const MeshSearch& search) {
  std::vector<std::filesystem::path> allowed = search.package_paths;
  if (!search.description_folder.empty()) allowed.push_back(search.description_folder);
  for (const std::filesystem::path& folder : allowed) {
    const std::filesystem::path relative = path.lexically_relative(folder);
    if (relative.empty() || *relative.begin() == "..") continue;
    if (auto found = regularFileInside(folder, relative)) return *found;
  }
  return "'" + filename + "' is not a readable file inside the package paths";
}

}  // namespace

std::vector<std::filesystem::path> splitPackagePath(const std::string& ros_package_path) {
  std::vector<std::filesystem::path> folders;
  std::size_t start = 0;
  while (start <= ros_package_path.size()) {
    const std::size_t colon = std::min(ros_package_path.find(':', start), ros_package_path.size());
    if (colon > start) folders.emplace_back(ros_package_path.substr(start, colon - start));
    start = colon + 1;
  }
  return folders;
}

std::variant<std::filesystem::path, std::string> locateMesh(const std::string& filename,
                                                            const MeshSearch& search) {
  if (startsWith(filename, kPackageScheme)) return locatePackageFile(filename, search);
  std::filesystem::path path = filename;
  if (startsWith(filename, kFileScheme)) {
    path = filename.substr(kFileScheme.size());
    if (!path.is_absolute()) return "'" + filename + "' is not an absolute file:// path";
  } else if (filename.find("://") != std::string::npos) {
    return "'" + filename + "': only package:// and file:// are resolved";
  }
  if (path.is_absolute()) return locateAbsoluteFile(filename, path, search);
  if (search.description_folder.empty()) {
    return "'" + filename + "' is relative, and the description came with no folder";
  }
  if (auto found = regularFileInside(search.description_folder, path)) return *found;
  return "'" + filename + "' not found beside the description in '" +
         search.description_folder.string() + "'";
}

}  // namespace lcmtf::viewer
