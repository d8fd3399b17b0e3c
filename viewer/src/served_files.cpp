#include "lcmtf_viewer/served_files.hpp"

#include <algorithm>
#include <cctype>

#include "ascii_lowercase.hpp"

namespace lcmtf::viewer {

namespace {

std::string_view withoutQuery(std::string_view target) {
  return target.substr(0, std::min(target.find('?'), target.find('#')));
}

bool isPlainPathCharacter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '/' || c == '.' || c == '_' ||
         c == '-';
}

}  // namespace

void ServedFiles::add(const std::string& url_path, const std::filesystem::path& path) {
  files_[url_path] = ServedFile{path, contentTypeFor(path)};
}

const ServedFile* ServedFiles::find(std::string_view target) const {
  const auto found = files_.find(withoutQuery(target));
  return found == files_.end() ? nullptr : &found->second;
}

std::optional<std::string> refuseRequestTarget(std::string_view target) {
  const std::string_view path = withoutQuery(target);
  if (path.empty() || path.front() != '/') return "the path does not start with '/'";
  if (path.size() > 1024) return "the path is longer than 1024 characters";
  for (char c : path) {
    if (c == '%') return "the path is percent-encoded; no file served needs that";
    if (c == '\\') return "the path has a backslash";
    if (c == '\0') return "the path has a NUL character";
    if (!isPlainPathCharacter(c)) return "the path has a character no file served has";
  }
  if (path.find("..") != std::string_view::npos) return "the path has '..'";
  if (path.find("//") != std::string_view::npos) return "the path has an empty segment";
  return std::nullopt;
}

std::string contentTypeFor(const std::filesystem::path& path) {
  const std::string extension = asciiLowercase(path.extension().string());
  static const std::map<std::string, std::string, std::less<>> kTypes = {
      {".html", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},
      {".svg", "image/svg+xml"},
      {".png", "image/png"},
      {".jpg", "image/jpeg"},
      {".jpeg", "image/jpeg"},
      {".ico", "image/x-icon"},
      {".stl", "model/stl"},
      {".dae", "model/vnd.collada+xml"},
      {".txt", "text/plain; charset=utf-8"},
      {".md", "text/plain; charset=utf-8"}};
  const auto found = kTypes.find(extension);
  return found == kTypes.end() ? "application/octet-stream" : found->second;
}

}  // namespace lcmtf::viewer
