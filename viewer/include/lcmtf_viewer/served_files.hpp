#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace lcmtf::viewer {

/// A file the viewer will send: where it lies and what it is.
struct ServedFile {
  std::filesystem::path path;
  std::string content_type;
};

/// The only files the viewer serves, each under one exact URL path. A path is found or not:
/// nothing is joined to a directory, so no request can reach a file that was not listed.
class ServedFiles {
 public:
  /// Lists `path` under `url_path` ("/viewer.js"), its type from its extension.
  void add(const std::string& url_path, const std::filesystem::path& path);
  /// The file listed under the request target's path (a query string is ignored), or null.
  const ServedFile* find(std::string_view target) const;
  std::size_t size() const { return files_.size(); }

 private:
  std::map<std::string, ServedFile, std::less<>> files_;
};

/// Why a request target is refused before any lookup (a "..", a backslash, a percent sign,
/// a NUL or another character no listed path has), or nothing when it may be looked up.
std::optional<std::string> refuseRequestTarget(std::string_view target);

/// The MIME type for a file name's extension; "application/octet-stream" when unknown.
std::string contentTypeFor(const std::filesystem::path& path);

}  // namespace lcmtf::viewer
