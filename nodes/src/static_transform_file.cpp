#include "lcmtf/nodes/static_transform_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/programs/plain_text.hpp"

namespace lcmtf::nodes {

namespace {

// Files are small; this keeps a wrong path (a device, a huge log) from being read whole.
constexpr std::streamsize kMaxFileBytes = 16 * 1024 * 1024;

std::string where(const std::string& name, const YAML::Mark& mark) {
  if (mark.is_null()) return name;
  return name + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

std::string knownKeys() {
  std::string list;
  for (const std::string& key : staticTransformFileKeys()) list += (list.empty() ? "" : ", ") + key;
  return list;
}

bool isDocumentMarker(std::string_view line, std::string_view marker) {
  return line.substr(0, 3) == marker && (line.size() == 3 || line[3] == ' ' || line[3] == '\t');
}

bool isCommentOrBlank(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  return first == std::string_view::npos || line[first] == '#';
}

// The line (from 1) where a second YAML document begins in `text`, or 0: a document marker at
// the start of a line once the first document has content, or content after its end marker.
// yaml-cpp's YAML::LoadAll would tell, but it never returns on some malformed text (",").
std::size_t secondDocumentLine(std::string_view text) {
  bool content = false;
  bool ended = false;
  std::size_t number = 0;
  for (std::size_t start = 0; start <= text.size(); ++number) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (isDocumentMarker(line, "...")) {
      ended = ended || content;
      continue;
    }
    if (isDocumentMarker(line, "---")) {
      if (content || ended) return number + 1;
      line.remove_prefix(3);
    }
    if (isCommentOrBlank(line) || (!content && line.front() == '%')) continue;
    if (ended) return number + 1;
    content = true;
  }
  return 0;
}

std::string scalar(const YAML::Node& value, const std::string& key, const std::string& at) {
  if (value.IsNull()) throw CommandLineError(at + ": '" + key + "' has no value");
  if (!value.IsScalar()) throw CommandLineError(at + ": '" + key + "' must be a single value");
  return value.Scalar();
}

StaticTransformSpec parseEntry(const YAML::Node& entry, const std::string& name,
                               std::size_t index) {
  StaticTransformSpec spec;
  spec.origin = where(name, entry.Mark()) + " (transform " + std::to_string(index + 1) + ")";
  if (!entry.IsMap()) {
    throw CommandLineError(spec.origin + ": a transform must be a map of keys (" + knownKeys() +
                           ")");
  }
  Eigen::Vector4d quaternion = Eigen::Vector4d::Zero();
  RollPitchYaw angles;
  bool has_quaternion = false;
  bool has_angles = false;
  const std::map<std::string, std::pair<double*, bool*>> numbers{
      {"x", {&spec.translation.x(), nullptr}},    {"y", {&spec.translation.y(), nullptr}},
      {"z", {&spec.translation.z(), nullptr}},    {"qx", {&quaternion.x(), &has_quaternion}},
      {"qy", {&quaternion.y(), &has_quaternion}}, {"qz", {&quaternion.z(), &has_quaternion}},
      {"qw", {&quaternion.w(), &has_quaternion}}, {"roll", {&angles.roll, &has_angles}},
      {"pitch", {&angles.pitch, &has_angles}},    {"yaw", {&angles.yaw, &has_angles}}};
  std::set<std::string> seen;
  for (const auto& item : entry) {
    const std::string at = where(name, item.first.Mark());
    const std::string key = item.first.IsScalar() ? item.first.Scalar() : std::string("?");
    const auto number = numbers.find(key);
    if (number == numbers.end() && key != "frame_id" && key != "child_frame_id") {
      throw CommandLineError(at + ": unknown key '" + key + "' (known: " + knownKeys() + ")");
    }
    if (!seen.insert(key).second) throw CommandLineError(at + ": key '" + key + "' given twice");
    const std::string text = scalar(item.second, key, at);
    if (key == "frame_id") {
      spec.frame_id = text;
    } else if (key == "child_frame_id") {
      spec.child_frame_id = text;
    } else {
      *number->second.first = parseFiniteNumber(text, where(name, item.second.Mark()) + ": " + key);
      if (number->second.second) *number->second.second = true;
    }
  }
  if (has_quaternion) spec.quaternion_xyzw = quaternion;
  if (has_angles) spec.roll_pitch_yaw = angles;
  return spec;
}

}  // namespace

const std::vector<std::string>& staticTransformFileKeys() {
  static const std::vector<std::string> keys{
      "frame_id", "child_frame_id", "x", "y", "z", "qx", "qy", "qz", "qw", "roll", "pitch", "yaw"};
  return keys;
}

std::vector<StaticTransformSpec> parseStaticTransformYaml(const std::string& text,
                                                          const std::string& name) {
  // yaml-cpp stops at a NUL byte of UTF-8 text with a misleading message ("unknown escape
  // character").
  if (const std::size_t nul = text.find('\0');
      nul != std::string::npos && !programs::isUtf16Or32(text)) {
    const programs::TextPosition at = programs::positionOf(text, nul);
    throw CommandLineError(name + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                           ": not valid YAML: a NUL byte (YAML text has none)");
  }
  if (const std::size_t line = secondDocumentLine(text); line > 0) {
    throw CommandLineError(name + ":" + std::to_string(line) +
                           ": a second YAML document: put every transform in the one list");
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw CommandLineError(
        where(name, e.mark) + ": not valid YAML: nested deeper than the YAML reader goes (" +
        std::to_string(e.depth()) + " levels; a transform file nests 3 at most)");
  } catch (const YAML::Exception& e) {
    throw CommandLineError(where(name, e.mark) + ": not valid YAML: " + e.msg);
  }
  YAML::Node list = root;
  if (root.IsMap()) {
    if (!root["transforms"]) {
      throw CommandLineError(where(name, root.Mark()) +
                             ": expected a list of transforms, or a map with the key "
                             "'transforms' holding that list");
    }
    for (const auto& entry : root) {
      const std::string key = entry.first.Scalar();
      if (key != "transforms") {
        throw CommandLineError(where(name, entry.first.Mark()) + ": unknown key '" + key +
                               "' (the only one at the top is 'transforms')");
      }
    }
    list = root["transforms"];
  }
  if (!list.IsSequence() || list.size() == 0) {
    throw CommandLineError(where(name, list.Mark()) +
                           ": expected a non-empty list of transforms, each a map of keys (" +
                           knownKeys() + ")");
  }
  std::vector<StaticTransformSpec> specs;
  for (std::size_t index = 0; index < list.size(); ++index) {
    specs.push_back(parseEntry(list[index], name, index));
  }
  return specs;
}

std::vector<StaticTransformSpec> loadStaticTransformFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw CommandLineError("--file: cannot read '" + path + "': " + std::strerror(errno));
  }
  std::ostringstream text;
  std::vector<char> chunk(65536);
  std::streamsize total = 0;
  while (file.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || file.gcount() > 0) {
    total += file.gcount();
    if (total > kMaxFileBytes) {
      throw CommandLineError("--file: '" + path + "' is larger than 16 MiB; not a transform file");
    }
    text.write(chunk.data(), file.gcount());
  }
  if (file.bad()) {
    throw CommandLineError("--file: cannot read '" + path + "': " + std::strerror(errno));
  }
  return parseStaticTransformYaml(text.str(), path);
}

}  // namespace lcmtf::nodes
