// Every program follows one command-line convention: --help and --version exit 0, a bad
// argument, a file it names or --lcm-url exits 2 naming it, and a program that talks says on
// which URL.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "support/child_process.hpp"
#include "support/test_lcm.hpp"

namespace {

using namespace std::chrono_literals;
using lcmtf_test::ChildProcess;
using testing::HasSubstr;

struct Program {
  std::string path;
  std::vector<std::string> needed;  ///< arguments without which it would not run
  bool publishes_transforms = true;
  bool runs_until_stopped = false;
};

void PrintTo(const Program& program, std::ostream* out) {
  *out << program.path.substr(program.path.rfind('/') + 1);
}

std::string nameOf(const Program& program) {
  return program.path.substr(program.path.rfind('/') + 1);
}

std::vector<std::string> with(std::vector<std::string> arguments,
                              const std::vector<std::string>& needed) {
  arguments.insert(arguments.end(), needed.begin(), needed.end());
  return arguments;
}

class EveryProgram : public testing::TestWithParam<Program> {};

TEST_P(EveryProgram, HelpTeachesTheSharedOptionsAndExitsZero) {
  ChildProcess program(GetParam().path, {"--help"});
  ASSERT_EQ(program.waitForExit(10s), std::optional<int>(0)) << program.stderrText();
  std::vector<std::string> taught{"Usage:", "--lcm-url", "--version",
                                  "Examples:", "Exit status: 0 on success, 1 when"};
  if (GetParam().publishes_transforms) taught.push_back("--static-channel");
  for (const std::string& option : taught) {
    EXPECT_THAT(program.stdoutText(), HasSubstr(option));
  }
}

TEST_P(EveryProgram, VersionNamesTheProgramAndExitsZero) {
  ChildProcess program(GetParam().path, {"--version"});
  ASSERT_EQ(program.waitForExit(10s), std::optional<int>(0)) << program.stderrText();
  EXPECT_THAT(
      program.stdoutText(),
      testing::MatchesRegex(nameOf(GetParam()) + " \\(lcmtf\\) [0-9]+\\.[0-9]+\\.[0-9]+\n"));
}

TEST_P(EveryProgram, AnUnknownOptionExitsTwoNamingIt) {
  ChildProcess program(GetParam().path, with({"--frobnicate"}, GetParam().needed));
  ASSERT_EQ(program.waitForExit(10s), std::optional<int>(2)) << program.stderrText();
  EXPECT_THAT(program.stderrText(), HasSubstr(nameOf(GetParam()) + ": "));
  EXPECT_THAT(program.stderrText(), HasSubstr("--frobnicate"));
  EXPECT_THAT(program.stderrText(), HasSubstr("Run '" + nameOf(GetParam()) + " --help'"));
}

TEST_P(EveryProgram, AnLcmUrlThatCannotBeOpenedExitsTwoNamingIt) {
  ChildProcess program(GetParam().path, with({"--lcm-url", "bogus://"}, GetParam().needed));
  ASSERT_EQ(program.waitForExit(10s), std::optional<int>(2)) << program.stderrText();
  EXPECT_THAT(program.stderrText(),
              HasSubstr(nameOf(GetParam()) + ": --lcm-url: cannot open LCM at 'bogus://'"));
}

TEST_P(EveryProgram, ARunningProgramSaysTheUrlItTalksOn) {
  if (!GetParam().runs_until_stopped) GTEST_SKIP() << "says its URL only in its messages";
  const auto* test = testing::UnitTest::GetInstance()->current_test_info();
  const std::string url = lcmtf_test::privateUdpmUrl(test->name());
  setenv("LCM_DEFAULT_URL", url.c_str(), 1);  // no --lcm-url: the URL of the environment
  ChildProcess program(GetParam().path, GetParam().needed);
  EXPECT_TRUE(program.waitForStdout(url, 10s)) << program.stdoutText() << program.stderrText();
  program.interrupt();
  EXPECT_EQ(program.waitForExit(10s), std::optional<int>(0)) << program.stderrText();
}

const std::vector<std::string> kPose{"0", "0", "0", "0", "0", "0", "base", "camera"};

// A file named on the command line is an argument too: one that is not there exits 2.
TEST(ProgramsReadingFiles, AFileThatIsNotThereExitsTwoNamingIt) {
  const std::string missing = "/nonexistent-folder/robot.urdf";
  const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {LCMTF_STATIC_PUBLISHER_PATH, {"--file", "/nonexistent-folder/mounts.yaml"}},
      {LCMTF_URDF_PUBLISHER_PATH, {missing}},
      {LCMTF_JOINT_PUBLISHER_PATH, {missing}},
      {LCMTF_VIEWER_PATH, {"--port", "0", "--urdf", missing}}};
  for (const auto& [path, arguments] : runs) {
    ChildProcess program(path, with({"--lcm-url", "memq://"}, arguments));
    EXPECT_EQ(program.waitForExit(10s), std::optional<int>(2)) << path << program.stderrText();
    EXPECT_THAT(program.stderrText(), HasSubstr("/nonexistent-folder/")) << path;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Programs, EveryProgram,
    testing::Values(Program{LCMTF_STATIC_PUBLISHER_PATH, kPose, true, true},
                    Program{LCMTF_ECHO_PATH, {"map", "base"}}, Program{LCMTF_MONITOR_PATH, {}},
                    Program{LCMTF_VIEW_FRAMES_PATH, {}},
                    Program{LCMTF_URDF_PUBLISHER_PATH, {EXAMPLE_URDF}, true, true},
                    Program{LCMTF_JOINT_PUBLISHER_PATH, {EXAMPLE_URDF}, false, true},
                    Program{LCMTF_VIEWER_PATH, {"--port", "0"}, true, true}),
    [](const testing::TestParamInfo<Program>& param) {
      std::string name = nameOf(param.param).substr(6);  // without "lcmtf-"
      for (char& c : name) c = c == '-' ? '_' : c;
      return name;
    });

}  // namespace
