#include "lcmtf_viewer/web_assets.hpp"

#include <unistd.h>

#include <stdexcept>
#include <system_error>

namespace lcmtf::viewer {

namespace {

std::filesystem::path ownExecutable() {
  std::error_code error;
  return std::filesystem::read_symlink("/proc/self/exe", error);
}

}  // namespace

const std::vector<std::string>& threeJsFiles() {
  static const std::vector<std::string> kFiles = {
      "build/three.module.js", "examples/jsm/controls/OrbitControls.js",
      "examples/jsm/loaders/STLLoader.js", "examples/jsm/loaders/ColladaLoader.js",
      "examples/jsm/loaders/TGALoader.js"};
  return kFiles;
}

std::filesystem::path defaultWebRoot() {
  const std::filesystem::path installed =
      ownExecutable().parent_path().parent_path() / "share" / "lcmtf" / "viewer";
  std::error_code error;
  if (std::filesystem::is_regular_file(installed / "index.html", error)) return installed;
  return LCMTF_VIEWER_SOURCE_WEB_ROOT;
}

ServedFiles pageFiles(const std::filesystem::path& web_root,
                      const std::filesystem::path& three_dir) {
  ServedFiles files;
  std::error_code error;
  if (!std::filesystem::is_regular_file(web_root / "index.html", error)) {
    throw std::runtime_error("the page's folder '" + web_root.string() + "' has no index.html");
  }
  files.add("/", web_root / "index.html");
  for (std::filesystem::recursive_directory_iterator entry(web_root, error), end;
       !error && entry != end; entry.increment(error)) {
    if (!entry->is_regular_file(error)) continue;
    const std::string relative = entry->path().lexically_relative(web_root).generic_string();
    if (refuseRequestTarget("/" + relative)) continue;  // a name no URL path could carry
    files.add("/" + relative, entry->path());
  }
  for (const std::string& relative : threeJsFiles()) {
    const std::filesystem::path path = three_dir / relative;
    if (!std::filesystem::is_regular_file(path, error)) {
      throw std::runtime_error("three.js file '" + path.string() +
                               "' is missing (Debian: apt-get install libjs-three)");
    }
    files.add("/three/" + relative, path);
  }
  return files;
}

}  // namespace lcmtf::viewer
