// libFuzzer target: text as a static transform file (lcmtf-static-publisher --file), through the
// YAML reader and the checks every transform gets. Any crash, sanitizer report or exception but
// CommandLineError is a bug; so is a refusal that does not name the file, a transform let
// through that is not finite, unit-rotated and between two different named frames, and a file
// that, written out again with its names quoted as lcmtf-view-frames quotes them, reads back
// different.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_check.hpp"
#include "lcmtf/nodes/static_transform_file.hpp"
#include "lcmtf/nodes/static_transform_spec.hpp"
#include "lcmtf/printable.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/programs/roll_pitch_yaw.hpp"

namespace {

using lcmtf::nodes::StaticTransformSpec;
using lcmtf_fuzz::fail;

constexpr const char* kFileName = "fuzz.yaml";

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// The specs as a file a person could have written, every value given.
std::string written(const std::vector<StaticTransformSpec>& specs) {
  std::string text;
  for (const StaticTransformSpec& spec : specs) {
    text += "- {frame_id: " + lcmtf::yamlQuoted(spec.frame_id) +
            ", child_frame_id: " + lcmtf::yamlQuoted(spec.child_frame_id);
    const char* const axes[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      text += std::string(", ") + axes[i] + ": " + number(spec.translation[i]);
    }
    if (spec.quaternion_xyzw) {
      const char* const keys[] = {"qx", "qy", "qz", "qw"};
      for (int i = 0; i < 4; ++i) {
        text += std::string(", ") + keys[i] + ": " + number((*spec.quaternion_xyzw)[i]);
      }
    }
    if (spec.roll_pitch_yaw) {
      text += ", roll: " + number(spec.roll_pitch_yaw->roll) +
              ", pitch: " + number(spec.roll_pitch_yaw->pitch) +
              ", yaw: " + number(spec.roll_pitch_yaw->yaw);
    }
    text += "}\n";
  }
  return text;
}

// yamlQuoted shows a byte of malformed UTF-8 as the character of its value, which reads back
// as two bytes: names with bytes above ASCII are only required to read back the same the
// second time round.
bool sameName(const std::string& read_back, const std::string& original, bool exact) {
  if (read_back == original) return true;
  return !exact && std::any_of(original.begin(), original.end(),
                               [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
}

bool sameAngles(const std::optional<lcmtf::programs::RollPitchYaw>& a,
                const std::optional<lcmtf::programs::RollPitchYaw>& b) {
  if (!a || !b) return a.has_value() == b.has_value();
  return a->roll == b->roll && a->pitch == b->pitch && a->yaw == b->yaw;
}

bool sameSpecs(const std::vector<StaticTransformSpec>& a, const std::vector<StaticTransformSpec>& b,
               bool exact_names) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!sameName(b[i].frame_id, a[i].frame_id, exact_names) ||
        !sameName(b[i].child_frame_id, a[i].child_frame_id, exact_names) ||
        a[i].translation != b[i].translation || a[i].quaternion_xyzw != b[i].quaternion_xyzw ||
        !sameAngles(a[i].roll_pitch_yaw, b[i].roll_pitch_yaw)) {
      return false;
    }
  }
  return true;
}

std::vector<StaticTransformSpec> readBack(const std::string& text) {
  try {
    return lcmtf::nodes::parseStaticTransformYaml(text, kFileName);
  } catch (const lcmtf::programs::CommandLineError& e) {
    fail("a file written from what was read was refused", std::string(e.what()) + "\n" + text);
  }
}

void checkReadsBackTheSame(const std::vector<StaticTransformSpec>& specs) {
  const std::string once = written(specs);
  const std::vector<StaticTransformSpec> read_once = readBack(once);
  if (!sameSpecs(specs, read_once, false)) fail("written out, the file read back different", once);
  const std::string twice = written(read_once);
  if (!sameSpecs(read_once, readBack(twice), true)) {
    fail("written out twice, the file read back different", twice);
  }
}

void checkTransforms(const std::vector<lcmtf::TransformStamped>& transforms, std::size_t count) {
  if (transforms.size() != count) fail("a transform was lost or made up", "");
  for (const lcmtf::TransformStamped& t : transforms) {
    if (t.parent_frame.empty() || t.child_frame.empty() || t.parent_frame == t.child_frame) {
      fail("a transform between frames that are missing or the same got through", t.child_frame);
    }
    if (!t.transform.translation.allFinite() ||
        !(std::abs(t.transform.rotation.norm() - 1.0) <= 1e-12)) {
      fail("a translation that is not finite or a rotation that is not unit got through",
           t.child_frame);
    }
  }
}

void checkRefusal(const lcmtf::programs::CommandLineError& e) {
  const std::string_view message = e.what();
  if (message.find(kFileName) == std::string_view::npos) fail("a refusal names no file", message);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<StaticTransformSpec> specs;
  try {
    specs = lcmtf::nodes::parseStaticTransformYaml(text, kFileName);
  } catch (const lcmtf::programs::CommandLineError& e) {
    checkRefusal(e);
    return 0;
  }
  if (specs.empty()) fail("an empty list of transforms was accepted", text);
  checkReadsBackTheSame(specs);
  try {
    checkTransforms(lcmtf::nodes::toStaticTransforms(specs, lcmtf::TimePoint{}), specs.size());
  } catch (const lcmtf::programs::CommandLineError& e) {
    checkRefusal(e);
  }
  return 0;
}
