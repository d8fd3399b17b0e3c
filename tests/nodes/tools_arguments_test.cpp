// Every tool, run as a process, refuses each bad argument with exit status 2 and a message
// that names it (tests/programs/program_conventions_test.cpp checks what all programs share).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "support/child_process.hpp"

namespace {

using namespace std::chrono_literals;
using lcmtf_test::ChildProcess;
using testing::HasSubstr;

struct BadCall {
  std::string program;
  std::vector<std::string> arguments;
  std::string named;  ///< what the message must contain
};

void PrintTo(const BadCall& call, std::ostream* out) {
  *out << call.program.substr(call.program.rfind('/') + 1);
  for (const std::string& argument : call.arguments) *out << " '" << argument << "'";
}

class BadArgument : public testing::TestWithParam<BadCall> {};

TEST_P(BadArgument, ExitsTwoWithAMessageNamingIt) {
  const BadCall& call = GetParam();
  ChildProcess tool(call.program, call.arguments);
  ASSERT_EQ(tool.waitForExit(10s), std::optional<int>(2)) << tool.stderrText();
  const std::string program = call.program.substr(call.program.rfind('/') + 1);
  EXPECT_THAT(tool.stderrText(), HasSubstr(program + ": "));
  EXPECT_THAT(tool.stderrText(), HasSubstr(call.named));
  EXPECT_EQ(tool.stdoutText(), "");
}

// LCM's udpm self test fails on port 0, which its test datagram never comes back from, after
// waiting 10 s for it.
TEST(ToolsLcm, AnLcmThatCannotReceiveExitsTwoSayingSo) {
  const std::string url = "udpm://239.255.76.67:0?ttl=0";
  ChildProcess echo(LCMTF_ECHO_PATH, {"map", "base", "--once", "--lcm-url", url});
  ASSERT_EQ(echo.waitForExit(60s), std::optional<int>(2)) << echo.stderrText();
  EXPECT_THAT(echo.stderrText(),
              HasSubstr("lcmtf-echo: --lcm-url: LCM at '" + url + "' cannot receive"));
}

TEST(ToolsLcm, AUrlFromTheEnvironmentThatCannotBeOpenedIsSaidToComeFromThere) {
  setenv("LCM_DEFAULT_URL", "bogus://", 1);
  ChildProcess echo(LCMTF_ECHO_PATH, {"map", "base"});
  unsetenv("LCM_DEFAULT_URL");
  ASSERT_EQ(echo.waitForExit(10s), std::optional<int>(2)) << echo.stderrText();
  EXPECT_THAT(echo.stderrText(),
              HasSubstr("lcmtf-echo: $LCM_DEFAULT_URL: cannot open LCM at 'bogus://'"));
}

const std::vector<std::string> kPose{"0", "0", "0", "0", "0", "0", "base", "camera"};

std::vector<std::string> withPose(std::vector<std::string> arguments) {
  arguments.insert(arguments.end(), kPose.begin(), kPose.end());
  return arguments;
}

INSTANTIATE_TEST_SUITE_P(
    StaticPublisher, BadArgument,
    testing::Values(
        BadCall{LCMTF_STATIC_PUBLISHER_PATH, {}, "nothing to publish"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH,
                {"0", "0", "0", "0", "0", "1", "1", "base", "camera"},
                "the quaternion (qx qy qz qw) = (0 0 1 1) has norm 1.414214"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH,
                {"--frame-id", "a", "--child-frame-id", "b", "--qw", "1", "--roll", "1"},
                "--qx/--qy/--qz/--qw and --roll/--pitch/--yaw both given"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH, {"1", "2", "3", "a", "b"}, "got 5 positional"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH,
                {"--frame-id", "a", "--child-frame-id", "b", "--x", "abc"},
                "--x: 'abc' is not a finite number"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH, {"--frame-id", "a"}, "--child-frame-id is required"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH,
                {"0", "0", "0", "0", "0", "0", "base", "base"},
                "frame 'base' cannot be its own parent"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH,
                {"--file", "/nonexistent/mounts.yaml"},
                "--file: cannot read '/nonexistent/mounts.yaml'"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH, withPose({"--period", "-1"}), "--period"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH, withPose({"--authority", ""}), "--authority"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH, withPose({"--lcm-url", "bogus://"}),
                "--lcm-url: cannot open LCM at 'bogus://'"},
        BadCall{LCMTF_STATIC_PUBLISHER_PATH, withPose({"--frobnicate"}), "--frobnicate"}));

INSTANTIATE_TEST_SUITE_P(
    Echo, BadArgument,
    testing::Values(
        BadCall{LCMTF_ECHO_PATH, {"map"}, "FRAME is required"},
        BadCall{LCMTF_ECHO_PATH, {"map", "base", "--rate", "0"}, "--rate"},
        BadCall{LCMTF_ECHO_PATH,
                {"map", "base", "--time", "noon"},
                "--time: 'noon' is not a finite number"},
        BadCall{LCMTF_ECHO_PATH, {"map", "base", "--precision", "99"}, "--precision"},
        BadCall{LCMTF_ECHO_PATH, {"map", "base", "--timeout", "0"}, "--timeout"},
        BadCall{LCMTF_ECHO_PATH, {"map", "base", "--static-channel", ""}, "--static-channel"},
        BadCall{LCMTF_ECHO_PATH,
                {"map", "base", "--lcm-url", "bogus://"},
                "--lcm-url: cannot open LCM at 'bogus://'"}));

INSTANTIATE_TEST_SUITE_P(
    Monitor, BadArgument,
    testing::Values(BadCall{LCMTF_MONITOR_PATH, {"map"}, "got 1 frame arguments"},
                    BadCall{LCMTF_MONITOR_PATH, {"--duration", "0"}, "--duration"},
                    BadCall{LCMTF_MONITOR_PATH, {"--duration", "forever"}, "--duration"},
                    BadCall{LCMTF_MONITOR_PATH, {"--max-stamp-ahead", "nan"}, "--max-stamp-ahead"},
                    BadCall{LCMTF_MONITOR_PATH,
                            {"--lcm-url", "bogus://"},
                            "--lcm-url: cannot open LCM at 'bogus://'"}));

INSTANTIATE_TEST_SUITE_P(
    ViewFrames, BadArgument,
    testing::Values(BadCall{LCMTF_VIEW_FRAMES_PATH, {"--wait", "-1"}, "--wait"},
                    BadCall{LCMTF_VIEW_FRAMES_PATH,
                            {"--lcm-url", "memq://", "--output", "/nonexistent/tree"},
                            "--output: cannot write '/nonexistent/tree.gv'"},
                    BadCall{LCMTF_VIEW_FRAMES_PATH, {"tree"}, "tree"}));

}  // namespace
