#include "lcmtf/nodes/view_frames.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <sstream>

#include "support/child_process.hpp"
#include "support/parsed_command_line.hpp"

namespace lcmtf::nodes {
namespace {

using testing::HasSubstr;

using Parsed = lcmtf_test::ParsedCommandLine<ViewFramesOptions>;

Parsed parse(const std::vector<std::string>& args) {
  return lcmtf_test::parseWith(&parseViewFramesCommandLine, args);
}

TEST(ViewFramesCommandLine, ReadsWaitOutputAndDotOnly) {
  const Parsed parsed = parse({"--wait", "1.5", "-o", "/tmp/tree", "--dot-only"});
  ASSERT_FALSE(parsed.status) << parsed.err;
  EXPECT_EQ(parsed.options.wait, std::chrono::milliseconds(1500));
  EXPECT_EQ(parsed.options.output, "/tmp/tree");
  EXPECT_FALSE(parsed.options.render);
  const Parsed defaults = parse({});
  EXPECT_EQ(defaults.options.wait, std::chrono::seconds(5));
  EXPECT_EQ(defaults.options.output, "frames");
  EXPECT_TRUE(defaults.options.render);
}

TEST(ViewFramesCommandLine, OutputMayBeGivenWithTheExtensionOfOneOfItsFiles) {
  EXPECT_EQ(parse({"--output", "again.gv"}).options.output, "again");
  EXPECT_EQ(parse({"--output", "/tmp/tree.pdf"}).options.output, "/tmp/tree");
  EXPECT_EQ(parse({"--output", "tree.svg"}).options.output, "tree");
  EXPECT_EQ(parse({"--output", "robot.v2"}).options.output, "robot.v2");
  EXPECT_EQ(parse({"--output", "/tmp/.gv"}).options.output, "/tmp/.gv");
}

TEST(ViewFramesCommandLine, AFolderNamedAsOneGetsTheFilesInside) {
  EXPECT_EQ(parse({"--output", "robot_trees/"}).options.output, "robot_trees/frames");
}

TEST(ViewFramesCommandLine, AFolderThereGetsTheFilesInside) {
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("view-frames");
  EXPECT_EQ(parse({"--output", directory.string()}).options.output,
            (directory / "frames").string());
  std::filesystem::remove_all(directory);
}

TEST(ViewFramesCommandLine, BadArgumentsAreNamed) {
  EXPECT_THAT(parse({"--wait", "0"}).err, HasSubstr("--wait: '0' is not a number in (0, 3600]"));
  EXPECT_THAT(parse({"--wait", "soon"}).err, HasSubstr("--wait: 'soon'"));
  EXPECT_THAT(parse({"--output", ""}).err, HasSubstr("--output"));
  EXPECT_THAT(parse({"frames"}).err, HasSubstr("frames"));
}

TEST(ViewFrames, OutputThatCannotBeWrittenIsReportedBeforeListening) {
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const auto started = std::chrono::steady_clock::now();
  const int status = viewFramesCommand(
      {"--lcm-url", "memq://", "--wait", "30", "--output", "/nonexistent-directory/frames"}, out,
      err, stop);
  EXPECT_EQ(status, kExitBadArguments);
  EXPECT_THAT(err.str(), HasSubstr("--output: cannot write '/nonexistent-directory/frames.gv'"));
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
}

TEST(ViewFrames, NothingHeardStillWritesTheGraphAndExitsOne) {
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("view-frames");
  const std::string output = (directory / "empty").string();
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status = viewFramesCommand(
      {"--lcm-url", "memq://", "--wait", "0.1", "--output", output, "--dot-only"}, out, err, stop);
  EXPECT_EQ(status, kExitFailure);
  EXPECT_THAT(out.str(), HasSubstr("Heard 0 edges (0 static) from 0 broadcasters, 0 conflicts."));
  EXPECT_THAT(out.str(), HasSubstr("Wrote " + output + ".gv\n"));
  EXPECT_THAT(err.str(), HasSubstr("nothing heard on TF and TF_STATIC at memq://"));
  EXPECT_TRUE(std::filesystem::exists(output + ".gv"));
  EXPECT_FALSE(std::filesystem::exists(output + ".pdf"));
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace lcmtf::nodes
