// lcmtf-monitor's command line and report, in-process.
#include "lcmtf/nodes/monitor.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <sstream>

#include "lcmtf/nodes/monitor_report.hpp"

#include "lcmtf/static_transform_broadcaster.hpp"
#include "support/clock_ahead_sender.hpp"
#include "support/parsed_command_line.hpp"
#include "support/test_lcm.hpp"
#include "support/wire_samples.hpp"

namespace lcmtf::nodes {
namespace {

using lcmtf_test::wireBatch;
using lcmtf_test::wireTransform;
using std::chrono::milliseconds;
using testing::HasSubstr;
using testing::Not;

constexpr TimePoint kStart = lcmtf_test::kToolsEpoch;

void send(TfTraffic& traffic, const std::string& authority, std::vector<transform_t> transforms,
          bool is_static, TimePoint received) {
  traffic.record(wireBatch(authority, std::move(transforms)), is_static, received);
}

// A small robot: map -> odom (static), odom -> base at 50 Hz, base -> camera (static),
// base -> arm at 10 Hz, and a second authority also sending base. The last odom -> base
// arrives after the window, so it is buffered but not counted in rates.
TrafficSummary robotSummary() {
  TfTraffic traffic;
  send(traffic, "mounts",
       {wireTransform("map", "odom", kStart), wireTransform("base", "camera", kStart)}, true,
       kStart);
  for (int i = 0; i < 51; ++i) {
    const TimePoint stamp = kStart + i * milliseconds(20);
    send(traffic, "driver", {wireTransform("odom", "base", stamp)}, false, stamp + milliseconds(2));
    if (i % 5 == 0)
      send(traffic, "arm", {wireTransform("base", "arm", stamp)}, false, stamp + milliseconds(8));
  }
  send(traffic, "stray", {wireTransform("map", "base", kStart)}, false, kStart + milliseconds(500));
  traffic.recordMalformed("TF", "truncated");
  return traffic.summarize(kStart, kStart + std::chrono::seconds(1), std::chrono::seconds(10));
}

TEST(MonitorReport, FramesAreListedAsATreeWithRatesDelaysAndBuffers) {
  const std::string report =
      formatMonitorReport(robotSummary(), "TF and TF_STATIC at memq://", nullptr);
  EXPECT_THAT(report, HasSubstr("Heard 5 edges from 4 authorities on TF and TF_STATIC at memq:// "
                                "in the 1.000 s up to 1700000001.000000."));
  // base's subtree hangs below the parent it is heard from most; the stray edge is a leaf.
  EXPECT_THAT(
      report,
      HasSubstr("  frame       parent  authority  rate Hz  delay avg ms   max ms  buffered\n"
                "  base        map     stray            -       500.000  500.000         1\n"
                "  odom        map     mounts           -        static        -         1\n"
                "    base      odom    driver       50.00         2.000    2.000        51\n"
                "      arm     base    arm          10.00         8.000    8.000        11\n"
                "      camera  base    mounts           -        static        -         1\n"));
}

TEST(MonitorReport, HostileNamesAreEscapedAndTheColumnsStillLineUp) {
  TfTraffic traffic;
  send(traffic, "evil\x1b[2J",
       {wireTransform("odom", "base\nfake row", kStart), wireTransform("odom", "arm", kStart)},
       true, kStart);
  const std::string report = formatMonitorReport(
      traffic.summarize(kStart, kStart + std::chrono::seconds(1), std::chrono::seconds(10)), "TF",
      nullptr);
  EXPECT_THAT(
      report,
      HasSubstr(
          "  frame             parent  authority    rate Hz  delay avg ms  max ms  buffered\n"
          "  arm               odom    evil\\x1b[2J        -        static       -         1\n"
          "  base\\x0afake row  odom    evil\\x1b[2J        -        static       -         1\n"));
  EXPECT_THAT(report, Not(HasSubstr("\x1b")));
}

TEST(MonitorReport, AuthoritiesConflictsAndProblemsAreListed) {
  const std::string report = formatMonitorReport(robotSummary(), "TF", nullptr);
  EXPECT_THAT(report,
              HasSubstr("Authorities:\n"
                        "  authority  messages  rate Hz  delay avg ms   max ms  frames\n"
                        "  mounts            1        -        static        -  camera, odom\n"
                        "  driver           50    50.00         2.000    2.000  base\n"
                        "  arm              10    10.00         8.000    8.000  arm\n"
                        "  stray             1        -       500.000  500.000  base\n"));
  EXPECT_THAT(report, HasSubstr("Conflicts (a frame sent by more than one authority):\n"
                                "  'base' from 'driver' (parent 'odom', dynamic, 50 transforms); "
                                "'stray' (parent 'map', dynamic, 1 transforms)\n"));
  EXPECT_THAT(report, HasSubstr("Problems since start (1 malformed messages, 0 invalid "
                                "transforms, 0 refused over limits):\n"
                                "  malformed messages (first, on TF: truncated)\n"));
}

TEST(MonitorReport, ChainAndItsNetDelayComeFirstAndItsFramesAreMarked) {
  ChainReport chain;
  chain.frame_a = "map";
  chain.frame_b = "arm";
  chain.frames = {"map", "odom", "base", "arm"};
  chain.samples = 60;
  chain.average_delay_s = 0.0125;
  chain.max_delay_s = 0.03;
  const std::string report = formatMonitorReport(robotSummary(), "TF", &chain);
  EXPECT_THAT(report, HasSubstr("Chain from 'map' to 'arm': map -> odom -> base -> arm\n"
                                "  net delay: average 12.500 ms, max 30.000 ms over 60 updates\n"));
  EXPECT_THAT(report, HasSubstr("Frames (* on the chain):"));
  EXPECT_THAT(report, HasSubstr("    base *    odom"));
  EXPECT_THAT(report, HasSubstr("      arm *   base"));
  EXPECT_THAT(report, HasSubstr("      camera  base"));
  EXPECT_LT(report.find("Chain from"), report.find("Frames"));
}

TEST(MonitorReport, MissingChainSaysWhy) {
  ChainReport chain;
  chain.frame_a = "map";
  chain.frame_b = "moon";
  chain.problem = "frame chain: source frame 'moon' does not exist";
  const std::string report = formatMonitorReport(TrafficSummary{}, "TF", &chain);
  EXPECT_THAT(report, HasSubstr("Chain from 'map' to 'moon': none yet: frame chain: source frame "
                                "'moon' does not exist"));
  EXPECT_THAT(report, HasSubstr("No transforms heard in this window."));
  EXPECT_THAT(report, Not(HasSubstr("Conflicts")));
}

using Parsed = lcmtf_test::ParsedCommandLine<MonitorOptions>;

Parsed parse(const std::vector<std::string>& args) {
  return lcmtf_test::parseWith(&parseMonitorCommandLine, args);
}

TEST(MonitorCommandLine, ReadsTheChainDurationAndContinuousMode) {
  const Parsed parsed = parse({"map", "base", "--duration", "2.5", "-c"});
  ASSERT_FALSE(parsed.status) << parsed.err;
  EXPECT_EQ(parsed.options.frame_a, "map");
  EXPECT_EQ(parsed.options.frame_b, "base");
  EXPECT_EQ(parsed.options.duration, milliseconds(2500));
  EXPECT_TRUE(parsed.options.continuous);
  const Parsed defaults = parse({});
  ASSERT_FALSE(defaults.status);
  EXPECT_EQ(defaults.options.duration, std::chrono::seconds(5));
  EXPECT_TRUE(defaults.options.frame_a.empty());
  EXPECT_FALSE(defaults.options.continuous);
}

TEST(MonitorCommandLine, BadArgumentsAreNamed) {
  EXPECT_THAT(parse({"map"}).err, HasSubstr("got 1 frame arguments: give two frames (A B)"));
  EXPECT_THAT(parse({"a", "b", "c"}).err, HasSubstr("got 3 frame arguments"));
  EXPECT_THAT(parse({"--duration", "0"}).err,
              HasSubstr("--duration: '0' is not a number in (0, 86400]"));
  EXPECT_THAT(parse({"--duration", "-3"}).err, HasSubstr("--duration"));
  EXPECT_THAT(parse({"--static-channel", ""}).err, HasSubstr("--static-channel"));
  EXPECT_EQ(parse({"--continuous=maybe"}).status, std::optional<int>(kExitBadArguments));
}

TEST(MonitorReport, BatchesLostReorderedOrDuplicatedAreListedPerAuthority) {
  TfTraffic traffic;
  const auto sendNumbered = [&](const std::string& authority, std::int64_t sequence,
                                bool is_static) {
    tf_message_t batch =
        wireBatch(authority, {wireTransform(authority, authority + "_child", kStart)});
    batch.sequence = sequence;
    traffic.record(batch, is_static, kStart + milliseconds(sequence));
  };
  for (std::int64_t n : {1, 2, 3, 6, 5, 5}) sendNumbered("driver", n, false);
  for (std::int64_t n : {1, 2, 3}) sendNumbered("driver", n, true);  // numbered apart
  for (std::int64_t n : {1, 2, 3, 4}) sendNumbered("arm", n, false);
  for (std::int64_t n : {300, 301, 1, 2}) sendNumbered("replay", n, false);
  const std::string report = formatMonitorReport(
      traffic.summarize(kStart, kStart + std::chrono::seconds(1), std::chrono::seconds(10)), "TF",
      nullptr);
  EXPECT_THAT(report,
              HasSubstr("Batches lost, reordered or duplicated on the way (by their numbers, "
                        "since start):\n"
                        "  authority  lost  reordered  duplicated  restarts\n"
                        "  driver        1          1           1         0\n"
                        "  replay        0          0           0         1\n"));
  EXPECT_THAT(report.substr(report.find("Batches lost")), Not(HasSubstr("arm")));
}

TEST(MonitorReport, NothingLostSaysNothingOfNumbers) {
  EXPECT_THAT(formatMonitorReport(robotSummary(), "TF", nullptr), Not(HasSubstr("Batches lost")));
}

TEST(Monitor, AChainToAnUnknownFrameExitsOneSuggestingTheFrameMeant) {
  const std::string url =
      lcmtf_test::privateUdpmUrl("Monitor.AChainToAnUnknownFrameExitsOneSuggestingTheFrameMeant");
  StaticBroadcasterOptions broadcaster_options;
  broadcaster_options.lcm_url = url;
  StaticTransformBroadcaster broadcaster(broadcaster_options);
  broadcaster.sendTransform({now(), "base", "gripper_tcp", Transform()});
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status =
      monitorCommand({"--lcm-url", url, "--duration", "1", "base", "gripper_tpc"}, out, err, stop);
  EXPECT_EQ(status, kExitFailure) << out.str();
  EXPECT_THAT(err.str(), HasSubstr("lcmtf-monitor: no chain from 'base' to 'gripper_tpc': "));
  EXPECT_THAT(err.str(), HasSubstr("'gripper_tpc' (did you mean 'gripper_tcp'?)"));
}

// A sender whose clock runs a minute ahead: its transforms are refused, and the report says so.
TEST(Monitor, TransformsRefusedAsStampedAheadAreListedAndExplainAMissingChain) {
  const std::string url = lcmtf_test::privateUdpmUrl("Monitor.TransformsRefusedAsStampedAhead");
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  int status = 0;
  {
    const lcmtf_test::ClockAheadSender sender(url);
    status = monitorCommand({"--lcm-url", url, "--duration", "1", "odom", "base"}, out, err, stop);
  }
  EXPECT_EQ(status, kExitFailure) << out.str();
  const std::string note =
      " refused as stamped more than 10.000000 s ahead of this machine's clock: synchronize the "
      "clocks, or take them with --max-stamp-ahead 0";
  EXPECT_THAT(out.str(), HasSubstr(note + "\n"));
  EXPECT_THAT(err.str(), HasSubstr("lcmtf-monitor: no chain from 'odom' to 'base': "));
  EXPECT_THAT(err.str(), HasSubstr(note + ")\n"));
}

TEST(Monitor, NothingHeardIsReportedAndExitsOne) {
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status = monitorCommand({"--lcm-url", "memq://", "--duration", "0.1"}, out, err, stop);
  EXPECT_EQ(status, kExitFailure);
  EXPECT_THAT(out.str(), HasSubstr("No transforms heard in this window."));
  EXPECT_THAT(err.str(), HasSubstr("lcmtf-monitor: nothing heard on TF and TF_STATIC at memq://"));
}

}  // namespace
}  // namespace lcmtf::nodes
