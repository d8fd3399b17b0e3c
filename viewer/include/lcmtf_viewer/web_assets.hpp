#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lcmtf_viewer/served_files.hpp"

namespace lcmtf::viewer {

/// The three.js files the page imports, relative to Debian's three.js folder; served at
/// "/three/<path>".
const std::vector<std::string>& threeJsFiles();

/// Debian's three.js folder (libjs-three).
inline constexpr const char* kDefaultThreeJsDir = "/usr/share/javascript/three";

/// The page's own folder: beside the program when installed (../share/lcmtf/viewer), else the
/// source tree's viewer/web it was built from.
std::filesystem::path defaultWebRoot();

/// Every regular file under `web_root` at "/<its path there>", "/" as index.html, and the
/// three.js files. Throws std::runtime_error naming what is missing.
ServedFiles pageFiles(const std::filesystem::path& web_root,
                      const std::filesystem::path& three_dir);

}  // namespace lcmtf::viewer
