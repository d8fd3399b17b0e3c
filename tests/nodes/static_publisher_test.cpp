// The static publisher's command line: the flag form, ROS's two positional forms, files, and
// every way they can be wrong.
#include "lcmtf/nodes/static_publisher.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/child_process.hpp"
#include "support/parsed_command_line.hpp"

namespace lcmtf::nodes {
namespace {

using testing::HasSubstr;

using Parsed = lcmtf_test::ParsedCommandLine<StaticPublisherOptions>;

Parsed parse(const std::vector<std::string>& args) {
  return lcmtf_test::parseWith(&parseStaticPublisherCommandLine, args);
}

// The one transform a successful parse gives.
TransformStamped only(const Parsed& parsed) {
  EXPECT_FALSE(parsed.status) << parsed.err;
  EXPECT_EQ(parsed.options.transforms.size(), 1u);
  return parsed.options.transforms.empty() ? TransformStamped{} : parsed.options.transforms[0];
}

Eigen::Quaterniond rpy(double roll, double pitch, double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
}

void expectRotation(const TransformStamped& transform, const Eigen::Quaterniond& expected) {
  EXPECT_LT(transform.transform.rotation.angularDistance(expected), 1e-12)
      << "got xyzw " << transform.transform.rotation.coeffs().transpose() << ", expected "
      << expected.coeffs().transpose();
}

// The message of a refused command line, after checking it was refused with status 2.
std::string refusal(const std::vector<std::string>& args) {
  const Parsed parsed = parse(args);
  EXPECT_EQ(parsed.status, std::optional<int>(kExitBadArguments)) << parsed.out;
  EXPECT_THAT(parsed.err, HasSubstr("lcmtf-static-publisher: "));
  return parsed.err;
}

TEST(StaticPublisherCommandLine, FlagsGiveTranslationAndRollPitchYaw) {
  const TransformStamped t =
      only(parse({"--frame-id", "base_link", "--child-frame-id", "camera", "--x", "0.1", "--y",
                  "-2", "--z", "3e-1", "--roll", "0.1", "--pitch", "-0.2", "--yaw", "1.5"}));
  EXPECT_EQ(t.parent_frame, "base_link");
  EXPECT_EQ(t.child_frame, "camera");
  EXPECT_EQ(t.transform.translation, Eigen::Vector3d(0.1, -2.0, 0.3));
  expectRotation(t, rpy(0.1, -0.2, 1.5));
}

TEST(StaticPublisherCommandLine, ValuesLeftOutAreZeroAndTheIdentity) {
  const TransformStamped t = only(parse({"--frame-id", "a", "--child-frame-id", "b", "--y", "4"}));
  EXPECT_EQ(t.transform.translation, Eigen::Vector3d(0.0, 4.0, 0.0));
  expectRotation(t, Eigen::Quaterniond::Identity());
}

TEST(StaticPublisherCommandLine, QuaternionComponentsLeftOutAreZero) {
  const TransformStamped t = only(parse({"--frame-id", "a", "--child-frame-id", "b", "--qz", "1"}));
  expectRotation(t, Eigen::Quaterniond(0.0, 0.0, 0.0, 1.0));
}

TEST(StaticPublisherCommandLine, EightPositionalArgumentsAreXYZYawPitchRollFrameChild) {
  const TransformStamped t = only(parse({"1", "2", "3", "0.5", "-0.25", "0.125", "map", "odom"}));
  EXPECT_EQ(t.parent_frame, "map");
  EXPECT_EQ(t.child_frame, "odom");
  EXPECT_EQ(t.transform.translation, Eigen::Vector3d(1.0, 2.0, 3.0));
  expectRotation(t, rpy(0.125, -0.25, 0.5));
}

TEST(StaticPublisherCommandLine, NinePositionalArgumentsAreXYZQuaternionFrameChild) {
  const TransformStamped t =
      only(parse({"-1", "0", "0.5", "0", "0", "0.7071068", "0.7071068", "base", "laser"}));
  EXPECT_EQ(t.transform.translation, Eigen::Vector3d(-1.0, 0.0, 0.5));
  expectRotation(t, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
  EXPECT_NEAR(t.transform.rotation.norm(), 1.0, 1e-15);
}

TEST(StaticPublisherCommandLine, NegativeFractionsWithoutALeadingZeroAreNumbers) {
  const TransformStamped positional = only(parse({"-.5", "0", "0", "-.25", "0", "0", "a", "b"}));
  EXPECT_EQ(positional.transform.translation.x(), -0.5);
  expectRotation(positional, rpy(0.0, 0.0, -0.25));
  const TransformStamped flags =
      only(parse({"--frame-id", "a", "--child-frame-id", "b", "--yaw", "-.25"}));
  expectRotation(flags, rpy(0.0, 0.0, -0.25));
}

TEST(StaticPublisherCommandLine, LeadingSlashOfAFrameNameIsDropped) {
  const TransformStamped t = only(parse({"0", "0", "0", "0", "0", "0", "/map", "/odom"}));
  EXPECT_EQ(t.parent_frame, "map");
  EXPECT_EQ(t.child_frame, "odom");
}

TEST(StaticPublisherCommandLine, NonUnitQuaternionIsRefusedNamingItsNorm) {
  EXPECT_THAT(refusal({"0", "0", "0", "0", "0", "1", "1", "a", "b"}),
              HasSubstr("has norm 1.414214"));
  EXPECT_THAT(refusal({"--frame-id", "a", "--child-frame-id", "b", "--qw", "0.5"}),
              HasSubstr("has norm 0.500000"));
  EXPECT_THAT(refusal({"0", "0", "0", "0", "0", "0", "0", "a", "b"}),
              HasSubstr("has norm 0.000000"));
}

TEST(StaticPublisherCommandLine, QuaternionWithinToleranceOfUnitIsNormalized) {
  const TransformStamped typed =
      only(parse({"0", "0", "0", "0", "0", "0.7071", "0.7071", "a", "b"}));
  EXPECT_NEAR(typed.transform.rotation.norm(), 1.0, 1e-15);
  expectRotation(typed, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
  const TransformStamped nearly = only(parse({"0", "0", "0", "0", "0", "0", "1.0009", "a", "b"}));
  EXPECT_NEAR(nearly.transform.rotation.norm(), 1.0, 1e-15);
  EXPECT_THAT(refusal({"0", "0", "0", "0", "0", "0.7", "0.7", "a", "b"}),
              HasSubstr("has norm 0.989949"));
}

TEST(StaticPublisherCommandLine, QuaternionAndRollPitchYawTogetherAreRefused) {
  EXPECT_THAT(refusal({"--frame-id", "a", "--child-frame-id", "b", "--qw", "1", "--yaw", "1"}),
              HasSubstr("--roll/--pitch/--yaw both given"));
}

TEST(StaticPublisherCommandLine, FlagsAndPositionalArgumentsTogetherAreRefused) {
  EXPECT_THAT(refusal({"--x", "1", "0", "0", "0", "0", "0", "0", "a", "b"}),
              HasSubstr("both as flags and as positional arguments"));
}

TEST(StaticPublisherCommandLine, WrongNumberOfPositionalArgumentsSaysWhatIsExpected) {
  EXPECT_THAT(refusal({"1", "2", "3", "a", "b"}),
              HasSubstr("got 5 positional arguments; expected 8 (x y z yaw pitch roll"));
  EXPECT_THAT(refusal({"0", "0", "0", "0", "0", "0", "1", "a", "b", "100"}),
              HasSubstr("trailing publishing period (ROS 1)"));
  EXPECT_THAT(refusal({"1", "2", "3", "0", "0", "0", "a", "b", "10"}),
              HasSubstr("got 9 positional arguments ending in a number: a trailing publishing "
                        "period (ROS 1) is not taken here"));
}

TEST(StaticPublisherCommandLine, PositionalValueThatIsNoNumberIsNamed) {
  EXPECT_THAT(refusal({"0", "0", "zero", "0", "0", "0", "a", "b"}),
              HasSubstr("positional argument 3 (z): 'zero' is not a finite number"));
  EXPECT_THAT(refusal({"0", "0", "0", "nan", "0", "0", "a", "b"}),
              HasSubstr("positional argument 4 (yaw): 'nan' is not a finite number"));
  EXPECT_THAT(refusal({"0", "0", "0", "0", "0", "inf", "1", "a", "b"}),
              HasSubstr("positional argument 6 (qz): 'inf'"));
}

TEST(StaticPublisherCommandLine, FlagValueThatIsNoNumberIsNamed) {
  EXPECT_THAT(refusal({"--frame-id", "a", "--child-frame-id", "b", "--z", "1m"}),
              HasSubstr("--z: '1m' is not a finite number"));
  EXPECT_THAT(refusal({"--frame-id", "a", "--child-frame-id", "b", "--roll", "inf"}),
              HasSubstr("--roll: 'inf' is not a finite number"));
}

TEST(StaticPublisherCommandLine, MissingOrRepeatedFrameNamesAreRefused) {
  EXPECT_THAT(refusal({"--frame-id", "a", "--x", "1"}), HasSubstr("--child-frame-id is required"));
  EXPECT_THAT(refusal({"--child-frame-id", "b"}), HasSubstr("--frame-id is required"));
  EXPECT_THAT(refusal({"--frame-id", "", "--child-frame-id", "b"}),
              HasSubstr("parent frame (frame_id) is missing or empty"));
  EXPECT_THAT(refusal({"0", "0", "0", "0", "0", "0", "/", "b"}),
              HasSubstr("parent frame (frame_id) is missing or empty"));
  EXPECT_THAT(refusal({"0", "0", "0", "0", "0", "0", "base", "/base"}),
              HasSubstr("frame 'base' cannot be its own parent"));
}

TEST(StaticPublisherCommandLine, NamesListenersWouldRefuseAreRefused) {
  const std::string longer(257, 'c');
  EXPECT_THAT(refusal({"0", "0", "0", "0", "0", "0", "base", longer}),
              HasSubstr("the child frame (child_frame_id) is 257 bytes long: listeners refuse a "
                        "batch with a name longer than 256 bytes"));
  EXPECT_THAT(refusal({"--authority", longer, "0", "0", "0", "0", "0", "0", "base", "camera"}),
              HasSubstr("--authority: is 257 bytes long"));
  EXPECT_FALSE(parse({"0", "0", "0", "0", "0", "0", "base", std::string(256, 'c')}).status);
}

TEST(StaticPublisherCommandLine, NothingToPublishIsRefused) {
  EXPECT_THAT(refusal({}), HasSubstr("nothing to publish"));
  EXPECT_THAT(refusal({"--period", "2"}), HasSubstr("nothing to publish"));
}

TEST(StaticPublisherCommandLine, UnknownOptionIsNamed) {
  EXPECT_THAT(refusal({"--frame-id", "a", "--child-frame-id", "b", "--quaternion", "1"}),
              HasSubstr("--quaternion"));
}

TEST(StaticPublisherCommandLine, PeriodOutsideItsRangeIsRefused) {
  EXPECT_THAT(refusal({"--period", "-1", "0", "0", "0", "0", "0", "0", "a", "b"}),
              HasSubstr("--period"));
  EXPECT_THAT(refusal({"--period", "nan", "0", "0", "0", "0", "0", "0", "a", "b"}),
              HasSubstr("--period: 'nan' is not a finite number"));
}

TEST(StaticPublisherCommandLine, PeriodAndAuthorityAreRead) {
  const Parsed parsed =
      parse({"--period", "0.25", "--authority", "mounts", "0", "0", "0", "0", "0", "0", "a", "b"});
  ASSERT_FALSE(parsed.status) << parsed.err;
  EXPECT_EQ(parsed.options.resend_period, std::chrono::milliseconds(250));
  EXPECT_EQ(parsed.options.authority, "mounts");
  const Parsed defaults = parse({"0", "0", "0", "0", "0", "0", "a", "b"});
  EXPECT_EQ(defaults.options.resend_period, std::chrono::seconds(1));
  EXPECT_THAT(defaults.options.authority, testing::StartsWith("lcmtf-static-publisher@"));
}

TEST(StaticPublisherCommandLine, FileAndFlagsCombineButAChildGivenTwiceIsRefused) {
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("static-publisher");
  const std::string file = (directory / "mounts.yaml").string();
  std::ofstream(file) << "- {frame_id: base, child_frame_id: camera, x: 0.5}\n"
                         "- {frame_id: base, child_frame_id: imu, qz: 1, qw: 0}\n";
  const Parsed parsed = parse({"--file", file, "--frame-id", "base", "--child-frame-id", "laser"});
  ASSERT_FALSE(parsed.status) << parsed.err;
  ASSERT_EQ(parsed.options.transforms.size(), 3u);
  EXPECT_EQ(parsed.options.transforms[0].child_frame, "laser");
  EXPECT_EQ(parsed.options.transforms[1].child_frame, "camera");
  EXPECT_EQ(parsed.options.transforms[2].child_frame, "imu");
  EXPECT_THAT(refusal({"--file", file, "--frame-id", "odom", "--child-frame-id", "camera"}),
              HasSubstr("frame 'camera' already has a parent, given at flags"));
  std::filesystem::remove_all(directory);
}

TEST(StaticPublisherCommandLine, APoseAfterAFileIsNotTakenForMoreFiles) {
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("static-publisher");
  const std::string file = (directory / "mounts.yaml").string();
  std::ofstream(file) << "- {frame_id: base, child_frame_id: camera, x: 0.5}\n";
  const Parsed parsed = parse({"--file", file, "0", "0", "1", "0", "0", "0", "odom", "base"});
  ASSERT_FALSE(parsed.status) << parsed.err;
  ASSERT_EQ(parsed.options.transforms.size(), 2u);
  EXPECT_EQ(parsed.options.transforms[0].child_frame, "base");
  EXPECT_EQ(parsed.options.transforms[1].child_frame, "camera");
  std::filesystem::remove_all(directory);
}

// YAML's "\e" is the escape character: a file could otherwise clear the screen or recolour it.
TEST(StaticPublisher, ControlCharactersFromAFileReachTheTerminalEscaped) {
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("static-publisher");
  const std::string bad_key = (directory / "bad_key.yaml").string();
  std::ofstream(bad_key) << "- {frame_id: base, child_frame_id: camera, \"\\e[2Jx\": 1}\n";
  const std::string message = refusal({"--file", bad_key});
  EXPECT_THAT(message, HasSubstr("unknown key '\\x1b[2Jx'"));
  EXPECT_EQ(message.find('\x1b'), std::string::npos);

  const std::string names = (directory / "names.yaml").string();
  std::ofstream(names) << "- {frame_id: \"b\\e[31mase\", child_frame_id: \"caf\u00e9\\a\"}\n";
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  EXPECT_EQ(staticPublisherCommand({"--check", "--file", names}, out, err, stop), kExitSuccess)
      << err.str();
  EXPECT_THAT(out.str(), HasSubstr("b\\x1b[31mase -> caf\u00e9\\x07: translation [0 0 0] m"));
  std::filesystem::remove_all(directory);
}

TEST(StaticPublisherCommandLine, HelpTeachesEveryFormAndExitsZero) {
  const Parsed parsed = parse({"--help"});
  EXPECT_EQ(parsed.status, std::optional<int>(kExitSuccess));
  for (const char* taught :
       {"x y z yaw pitch roll frame_id child_frame_id", "x y z qx qy qz qw frame_id child_frame_id",
        "--file", "--lcm-url", "--static-channel", "--period", "Rz(yaw) Ry(pitch) Rx(roll)",
        "Exit status"}) {
    EXPECT_THAT(parsed.out, HasSubstr(taught));
  }
}

TEST(StaticPublisherCommandLine, VersionIsTheProjectVersion) {
  const Parsed parsed = parse({"--version"});
  EXPECT_EQ(parsed.status, std::optional<int>(kExitSuccess));
  EXPECT_EQ(parsed.out, std::string("lcmtf-static-publisher (lcmtf) ") + toolsVersion() + "\n");
  EXPECT_THAT(toolsVersion(), testing::MatchesRegex("[0-9]+\\.[0-9]+\\.[0-9]+"));
}

TEST(StaticPublisher, CheckPrintsTheTransformsAndPublishesNothing) {
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status = staticPublisherCommand(
      {"--check", "--lcm-url", "invalid://", "1", "2", "3", "0", "0", "0", "base", "camera"}, out,
      err, stop);
  EXPECT_EQ(status, kExitSuccess) << err.str();
  EXPECT_THAT(out.str(), HasSubstr("nothing published"));
  EXPECT_THAT(out.str(),
              HasSubstr("base -> camera: translation [1 2 3] m, rotation xyzw [0 0 0 1]"));
}

TEST(StaticPublisher, UnusableLcmUrlIsNamed) {
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status = staticPublisherCommand(
      {"--lcm-url", "nonsense://", "0", "0", "0", "0", "0", "0", "a", "b"}, out, err, stop);
  EXPECT_EQ(status, kExitBadArguments);
  EXPECT_THAT(err.str(), HasSubstr("--lcm-url: cannot open LCM at 'nonsense://'"));
}

TEST(StaticPublisher, RunsUntilStoppedOnMemq) {
  std::ostringstream out, err;
  const std::atomic<bool> stop{true};
  const int status = staticPublisherCommand(
      {"--lcm-url", "memq://", "0", "0", "0", "0", "0", "0", "a", "b"}, out, err, stop);
  EXPECT_EQ(status, kExitSuccess) << err.str();
  EXPECT_THAT(out.str(), HasSubstr("Publishing 1 static transform on TF_STATIC at memq://"));
  EXPECT_THAT(out.str(), HasSubstr("Stopped after answering 0 requests."));
}

}  // namespace
}  // namespace lcmtf::nodes
