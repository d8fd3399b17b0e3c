#include "lcmtf/nodes/static_transform_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lcmtf/programs/command_line.hpp"
#include "support/child_process.hpp"

namespace lcmtf::nodes {
namespace {

using testing::AllOf;
using testing::HasSubstr;

// The message parseStaticTransformYaml refuses `text` with.
std::string refusal(const std::string& text) {
  try {
    toStaticTransforms(parseStaticTransformYaml(text, "mounts.yaml"), kLatestTime);
  } catch (const CommandLineError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

TEST(StaticTransformFile, ListOfTransformsWithEitherRotationFormIsRead) {
  const auto specs = parseStaticTransformYaml(
      "- frame_id: base_link\n"
      "  child_frame_id: camera\n"
      "  x: 0.1\n"
      "  z: -0.5\n"
      "  yaw: 1.5\n"
      "- {frame_id: base_link, child_frame_id: imu, y: 2, qx: 1, qw: 0}\n",
      "mounts.yaml");
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[0].frame_id, "base_link");
  EXPECT_EQ(specs[0].child_frame_id, "camera");
  EXPECT_EQ(specs[0].translation, Eigen::Vector3d(0.1, 0.0, -0.5));
  ASSERT_TRUE(specs[0].roll_pitch_yaw);
  EXPECT_EQ(specs[0].roll_pitch_yaw->yaw, 1.5);
  EXPECT_EQ(specs[0].roll_pitch_yaw->roll, 0.0);
  EXPECT_FALSE(specs[0].quaternion_xyzw);
  ASSERT_TRUE(specs[1].quaternion_xyzw);
  EXPECT_EQ(*specs[1].quaternion_xyzw, Eigen::Vector4d(1.0, 0.0, 0.0, 0.0));
  EXPECT_EQ(specs[1].translation, Eigen::Vector3d(0.0, 2.0, 0.0));
  EXPECT_THAT(specs[1].origin, HasSubstr("mounts.yaml:6:3 (transform 2)"));
}

TEST(StaticTransformFile, MapWithATransformsKeyIsRead) {
  const auto specs = parseStaticTransformYaml(
      "transforms:\n  - {frame_id: a, child_frame_id: b}\n  - {frame_id: b, child_frame_id: c}\n",
      "f.yaml");
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[1].child_frame_id, "c");
}

TEST(StaticTransformFile, UnknownKeyIsNamedWithItsLineAndColumn) {
  EXPECT_THAT(refusal("- frame_id: a\n  child_frame_id: b\n  yaww: 1\n"),
              HasSubstr("mounts.yaml:3:3: unknown key 'yaww' (known: frame_id, child_frame_id"));
}

// A transform under a misspelt key, or in a document of its own, would otherwise be left out.
TEST(StaticTransformFile, AnUnknownKeyBesideTransformsAndASecondDocumentAreRefused) {
  EXPECT_THAT(refusal("transforms:\n  - {frame_id: a, child_frame_id: b}\n"
                      "transform:\n  - {frame_id: a, child_frame_id: c}\n"),
              HasSubstr("mounts.yaml:3:1: unknown key 'transform' (the only one at the top is "
                        "'transforms')"));
  EXPECT_THAT(
      refusal("- {frame_id: a, child_frame_id: b}\n---\n- {frame_id: a, child_frame_id: c}\n"),
      HasSubstr("mounts.yaml:2: a second YAML document"));
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b}\n...\n# done\n- {frame_id: a}\n"),
              HasSubstr("mounts.yaml:4: a second YAML document"));
  const auto marked = parseStaticTransformYaml(
      "%YAML 1.2\n--- # one document, marked\n- {frame_id: a, child_frame_id: b}\n...\n", "f");
  EXPECT_EQ(marked.size(), 1u);
}

// yaml-cpp's reader of several documents never returns on this text.
TEST(StaticTransformFile, ALoneCommaIsRefused) {
  EXPECT_THAT(refusal(","), HasSubstr("mounts.yaml:1:1: expected a non-empty list of transforms"));
}

TEST(StaticTransformFile, ValueThatIsNoNumberIsNamedWithItsPosition) {
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b, x: one}\n"),
              HasSubstr("mounts.yaml:1:39: x: 'one' is not a finite number"));
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b, x: .nan}\n"),
              HasSubstr("x: '.nan' is not a finite number"));
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b, x: [1, 2]}\n"),
              HasSubstr("'x' must be a single value"));
  EXPECT_THAT(refusal("- frame_id: a\n  child_frame_id: b\n  x:\n"), HasSubstr("'x' has no value"));
}

TEST(StaticTransformFile, BrokenYamlIsReportedWithItsPosition) {
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b\n"),
              HasSubstr("mounts.yaml:2:1: not valid YAML"));
}

// The YAML reader calls this "bad file".
TEST(StaticTransformFile, YamlNestedDeeperThanTheReaderGoesIsSaidToBe) {
  for (const std::string& open : {std::string("["), std::string("{a: ")}) {
    std::string deep;
    for (int level = 0; level < 100'000; ++level) deep += open;
    EXPECT_THAT(refusal(deep),
                AllOf(HasSubstr(": not valid YAML: nested deeper than the YAML reader goes ("),
                      HasSubstr(" levels; a transform file nests 3 at most)")));
  }
}

TEST(StaticTransformFile, NulByteIsRefusedAtItsPlace) {
  EXPECT_EQ(refusal(std::string("- {frame_id: a, child_frame_id: b}\n- {frame_id: b\0", 50)),
            "mounts.yaml:2:15: not valid YAML: a NUL byte (YAML text has none)");
}

// As an editor may save it: each character two or four bytes, with or without a byte order mark.
TEST(StaticTransformFile, Utf16AndUtf32FilesAreRead) {
  const std::string ascii = "- {frame_id: base, child_frame_id: camera}\n";
  const auto widened = [&](std::size_t width, bool big_endian, const std::string& mark) {
    std::string text = mark;
    for (const char c : ascii) {
      std::string unit(width, '\0');
      unit[big_endian ? width - 1 : 0] = c;
      text += unit;
    }
    return text;
  };
  for (const std::string& text :
       {widened(2, false, "\xFF\xFE"), widened(2, true, "\xFE\xFF"), widened(2, false, ""),
        widened(2, true, ""), widened(4, false, std::string("\xFF\xFE\0\0", 4)),
        widened(4, true, "")}) {
    const auto specs = parseStaticTransformYaml(text, "wide.yaml");
    ASSERT_EQ(specs.size(), 1u);
    EXPECT_EQ(specs[0].frame_id, "base");
    EXPECT_EQ(specs[0].child_frame_id, "camera");
  }
}

TEST(StaticTransformFile, ShapesOtherThanAListOfMapsAreRefused) {
  EXPECT_THAT(refusal(""), HasSubstr("expected a non-empty list of transforms"));
  EXPECT_THAT(refusal("transforms: []\n"), HasSubstr("expected a non-empty list of transforms"));
  EXPECT_THAT(refusal("frame_id: a\nchild_frame_id: b\n"), HasSubstr("with the key 'transforms'"));
  EXPECT_THAT(refusal("- 1\n"), HasSubstr("(transform 1): a transform must be a map of keys"));
}

TEST(StaticTransformFile, RepeatedKeyIsRefused) {
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b, x: 1, x: 2}\n"),
              HasSubstr("key 'x' given twice"));
}

TEST(StaticTransformFile, EntriesAreCheckedLikeTheCommandLine) {
  EXPECT_THAT(refusal("- {frame_id: a, x: 1}\n"),
              HasSubstr("(transform 1): the child frame (child_frame_id) is missing or empty"));
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b, qz: 2}\n"),
              HasSubstr("has norm 2.000000"));
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b, qw: 1, roll: 0.1}\n"),
              HasSubstr("either as a quaternion (qx qy qz qw) or as roll/pitch/yaw"));
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b}\n- {frame_id: c, child_frame_id: b}\n"),
              HasSubstr("mounts.yaml:2:3 (transform 2): frame 'b' already has a parent, given at "
                        "mounts.yaml:1:3 (transform 1)"));
}

TEST(StaticTransformFile, ParentsThatLoopAreRefusedLinkByLink) {
  EXPECT_THAT(refusal("- {frame_id: a, child_frame_id: b}\n- {frame_id: b, child_frame_id: a}\n"),
              HasSubstr("loop, 'a' -> 'b' -> 'a' (given at mounts.yaml:1:3 (transform 1), "
                        "mounts.yaml:2:3 (transform 2)); frames must form a tree"));
  EXPECT_THAT(refusal("- {frame_id: map, child_frame_id: odom}\n"
                      "- {frame_id: odom, child_frame_id: b}\n"
                      "- {frame_id: d, child_frame_id: b2}\n"
                      "- {frame_id: b2, child_frame_id: c}\n"
                      "- {frame_id: c, child_frame_id: d}\n"),
              HasSubstr("'b2' -> 'c' -> 'd' -> 'b2'"));
}

TEST(StaticTransformFile, FileThatCannotBeReadIsNamed) {
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("transform-file");
  const std::string missing = (directory / "missing.yaml").string();
  try {
    loadStaticTransformFile(missing);
    ADD_FAILURE() << "read a missing file";
  } catch (const CommandLineError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--file: cannot read '" + missing + "'"));
  }
  try {
    loadStaticTransformFile(directory.string());
    ADD_FAILURE() << "read a directory";
  } catch (const CommandLineError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--file: cannot read '" + directory.string() + "'"));
  }
  const std::string good = (directory / "good.yaml").string();
  std::ofstream(good) << "- {frame_id: a, child_frame_id: b, z: 2}\n";
  const auto specs = loadStaticTransformFile(good);
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_EQ(specs[0].translation.z(), 2.0);
  EXPECT_THAT(specs[0].origin, HasSubstr(good + ":1:3"));
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace lcmtf::nodes
