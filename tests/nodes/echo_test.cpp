// lcmtf-echo's logic in-process: reading --time, printing a pose, saying what is missing.
#include "lcmtf/nodes/echo.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <sstream>
#include <thread>

#include "lcmtf/nodes/pose_text.hpp"
#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "support/clock_ahead_sender.hpp"
#include "support/parsed_command_line.hpp"
#include "support/test_lcm.hpp"

namespace lcmtf::nodes {
namespace {

using testing::HasSubstr;

constexpr TimePoint kStamp = fromUtime(1'700'000'000'250'000);

using Parsed = lcmtf_test::ParsedCommandLine<EchoOptions>;

Parsed parse(const std::vector<std::string>& args) {
  return lcmtf_test::parseWith(&parseEchoCommandLine, args);
}

TEST(EchoTime, PositiveSecondsAreAnInstantNegativeOnesAreBeforeNowZeroIsLatest) {
  const EchoTime fixed = parseEchoTime("1700000000.25");
  EXPECT_EQ(fixed.kind, EchoTime::Kind::kFixed);
  EXPECT_EQ(fixed.at(kStamp + std::chrono::seconds(3)), kStamp);

  const EchoTime before = parseEchoTime("-0.5");
  EXPECT_EQ(before.kind, EchoTime::Kind::kBeforeNow);
  EXPECT_EQ(before.at(kStamp), kStamp - std::chrono::milliseconds(500));

  EXPECT_EQ(parseEchoTime("0").at(kStamp), kLatestTime);
  EXPECT_EQ(EchoTime{}.at(kStamp), kLatestTime);
}

TEST(EchoTime, NonsenseIsRefusedNamingTheOption) {
  for (const char* text : {"yesterday", "nan", "", "1e300", "-100000"}) {
    try {
      parseEchoTime(text);
      ADD_FAILURE() << "accepted --time " << text;
    } catch (const CommandLineError& e) {
      EXPECT_THAT(e.what(), HasSubstr("--time: '" + std::string(text) + "'"));
    }
  }
}

TEST(EchoCommandLine, ReadsFramesAndOptions) {
  const Parsed parsed =
      parse({"map", "base_link", "--rate", "10", "--once", "--precision", "6", "--time", "-2",
             "--timeout", "1.5", "--lcm-url", "memq://", "--tf-channel", "MY_TF"});
  ASSERT_FALSE(parsed.status) << parsed.err;
  EXPECT_EQ(parsed.options.reference_frame, "map");
  EXPECT_EQ(parsed.options.frame, "base_link");
  EXPECT_EQ(parsed.options.rate_hz, 10.0);
  EXPECT_TRUE(parsed.options.once);
  EXPECT_EQ(parsed.options.precision, 6);
  EXPECT_EQ(parsed.options.time.before_now, std::chrono::seconds(2));
  EXPECT_EQ(parsed.options.timeout, std::optional<Duration>(std::chrono::milliseconds(1500)));
  EXPECT_EQ(parsed.options.connection.lcm_url, "memq://");
  EXPECT_EQ(parsed.options.connection.tf_channel, "MY_TF");
  EXPECT_EQ(parsed.options.connection.static_channel, "TF_STATIC");
  EXPECT_EQ(parsed.options.connection.max_stamp_ahead_s, 10.0);
  EXPECT_EQ(parse({"map", "base", "--max-stamp-ahead", "0"}).options.connection.max_stamp_ahead_s,
            0.0);
}

TEST(EchoCommandLine, OnceGivesUpAfterFiveSecondsUnlessToldOtherwise) {
  EXPECT_EQ(parse({"map", "base", "--once"}).options.timeout,
            std::optional<Duration>(std::chrono::seconds(5)));
  EXPECT_EQ(parse({"map", "base", "--once", "--timeout", "60"}).options.timeout,
            std::optional<Duration>(std::chrono::seconds(60)));
  EXPECT_EQ(parse({"map", "base"}).options.timeout, std::nullopt);
}

TEST(EchoCommandLine, OnceBeforeNowWaitsForThatMuchHistoryMore) {
  EXPECT_EQ(parse({"map", "base", "--once", "--time", "-20"}).options.timeout,
            std::optional<Duration>(std::chrono::seconds(25)));
  EXPECT_EQ(parse({"map", "base", "--once", "--time", "-20", "--timeout", "3"}).options.timeout,
            std::optional<Duration>(std::chrono::seconds(3)));
}

TEST(EchoCommandLine, BadArgumentsAreNamed) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"map"}, "FRAME is required"},
      {{}, "REFERENCE is required"},
      {{"map", "base", "extra"}, "extra"},
      {{"map", "base", "--rate", "0"}, "--rate: '0' is not a number in (0, 1000]"},
      {{"map", "base", "--rate", "fast"}, "--rate: 'fast'"},
      {{"map", "base", "--rate", "5000"}, "--rate"},
      {{"map", "base", "--precision", "40"}, "--precision"},
      {{"map", "base", "--precision", "-1"}, "--precision"},
      {{"map", "base", "--timeout", "-1"}, "--timeout: '-1' is not a number greater than zero"},
      {{"map", "base", "--time", "noon"}, "--time: 'noon' is not a finite number"},
      {{"map", "base", "--tf-channel", ""}, "--tf-channel"},
      {{"map", "base", "--max-stamp-ahead", "-1"}, "--max-stamp-ahead: '-1' is not a number in"},
      {{"", "base"}, "REFERENCE"},
  };
  for (const auto& [args, named] : cases) {
    const Parsed parsed = parse(args);
    EXPECT_EQ(parsed.status, std::optional<int>(kExitBadArguments)) << testing::PrintToString(args);
    EXPECT_THAT(parsed.err, HasSubstr(named)) << testing::PrintToString(args);
    EXPECT_THAT(parsed.err, HasSubstr("Run 'lcmtf-echo --help' for usage."));
  }
}

TEST(PoseText, PrintsStampAgeTranslationQuaternionAnglesAndMatrix) {
  const TransformStamped map_T_base{
      kStamp, "map", "base",
      Transform({1.0, -2.0, 0.5},
                Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())))};
  const std::string text = formatPose(map_T_base, kStamp + std::chrono::milliseconds(12), 3);
  EXPECT_EQ(text,
            "At 1700000000.250000 (age 0.012000 s): 'base' in 'map'\n"
            "  translation (m)    [1.000, -2.000, 0.500]\n"
            "  quaternion xyzw    [0.000, 0.000, 0.707, 0.707]\n"
            "  roll pitch yaw     [0.000, 0.000, 1.571] rad\n"
            "                     [0.000, 0.000, 90.000] deg\n"
            "  matrix             [ 0.000, -1.000,  0.000,  1.000]\n"
            "                     [ 1.000,  0.000,  0.000, -2.000]\n"
            "                     [ 0.000,  0.000,  1.000,  0.500]\n"
            "                     [ 0.000,  0.000,  0.000,  1.000]\n");
}

TEST(PoseText, RollPitchAndYawTogetherGiveTheQuaternionAnglesAndMatrixWorkedByHand) {
  // Rz(0.3) Ry(0.2) Rx(0.1), its quaternion and matrix worked out from the half-angle formulas.
  const Eigen::Quaterniond rotation(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()));
  const TransformStamped base_T_lidar{kStamp, "base", "lidar",
                                      Transform({1.0, 2.0, 3.0}, rotation)};
  const std::string text = formatPose(base_T_lidar, kStamp, 6);
  EXPECT_THAT(text,
              HasSubstr("  quaternion xyzw    [0.034271, 0.106021, 0.143572, 0.983347]\n"
                        "  roll pitch yaw     [0.100000, 0.200000, 0.300000] rad\n"
                        "                     [5.729578, 11.459156, 17.188734] deg\n"
                        "  matrix             [ 0.936293, -0.275096,  0.218351,  1.000000]\n"
                        "                     [ 0.289629,  0.956425, -0.036957,  2.000000]\n"
                        "                     [-0.198669,  0.097843,  0.975170,  3.000000]\n"));
}

TEST(PoseText, PrecisionSetsTheDigitsAndStaticChainsSayWhenTheyWereLookedUp) {
  const TransformStamped base_T_camera{
      kLatestTime, "base", "camera",
      Transform({0.123456789, 0.0, 0.0}, Eigen::Quaterniond::Identity())};
  const std::string text = formatPose(base_T_camera, kStamp, 7);
  EXPECT_THAT(text, HasSubstr("At " + toString(kStamp) +
                              ", static (every edge between them is static): 'camera' in 'base'"));
  EXPECT_THAT(text, HasSubstr("[0.1234568, 0.0000000, 0.0000000]"));
  EXPECT_EQ(fixedDecimals(-0.0004, 3), "0.000");
  EXPECT_EQ(fixedDecimals(-0.0006, 3), "-0.001");
}

TEST(EchoMissing, SaysNothingWasHeard) {
  BufferCore buffer;
  EXPECT_EQ(describeMissing(buffer, "map", "base", kLatestTime, false),
            "no transforms received yet");
}

TEST(EchoMissing, NamesUnknownFramesAndListsTheKnownOnes) {
  BufferCore buffer;
  buffer.setTransform({kStamp, "odom", "base", Transform()}, "test");
  EXPECT_EQ(describeMissing(buffer, "map", "base", kLatestTime, true),
            "frame 'map' is unknown; frames heard so far: base, odom");
  EXPECT_EQ(describeMissing(buffer, "map", "camera", kLatestTime, true),
            "frame 'map' and frame 'camera' are unknown; frames heard so far: base, odom");
}

TEST(EchoMissing, SuggestsTheFrameMeantAndListsTheClosestOfManyFirst) {
  BufferCore buffer;
  for (int i = 0; i < 40; ++i) {
    buffer.setTransform({kStamp, "base", "a_link_" + std::to_string(i), Transform()}, "test");
  }
  buffer.setTransform({kStamp, "base", "r_gripper_tool_frame", Transform()}, "test");
  const std::string missing =
      describeMissing(buffer, "base", "r_gripper_tool_frme", kLatestTime, true);
  EXPECT_THAT(missing, testing::StartsWith("frame 'r_gripper_tool_frme' (did you mean "
                                           "'r_gripper_tool_frame'?) is unknown; frames heard so "
                                           "far: r_gripper_tool_frame, "));
  EXPECT_THAT(missing, testing::EndsWith("(the 30 closest of 42)"));
}

TEST(EchoMissing, SaysWhyKnownFramesCannotBeLookedUp) {
  BufferCore buffer;
  buffer.setTransform({kStamp, "odom", "base", Transform()}, "test");
  buffer.setTransform({kStamp, "map", "landmark", Transform()}, "test");
  EXPECT_THAT(describeMissing(buffer, "map", "base", kLatestTime, true),
              HasSubstr("are not connected"));
  EXPECT_THAT(describeMissing(buffer, "odom", "base", kStamp + std::chrono::seconds(1), true),
              HasSubstr("extrapolation into the future"));
}

// A static broadcaster on `url` that sends its set again every 50 ms.
StaticBroadcasterOptions resendingOften(const std::string& url) {
  StaticBroadcasterOptions options;
  options.lcm_url = url;
  options.resend_period = std::chrono::milliseconds(50);
  return options;
}

TEST(Echo, RunPrintsThePoseOnceItArrives) {
  const std::string url = lcmtf_test::privateUdpmUrl("Echo.RunPrintsThePoseOnceItArrives");
  StaticTransformBroadcaster broadcaster(resendingOften(url));
  broadcaster.sendTransform({kStamp, "base", "camera", Transform({0.0, 0.0, 2.0}, {1, 0, 0, 0})});

  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status = echoCommand({"--lcm-url", url, "--once", "--timeout", "10", "base", "camera"},
                                 out, err, stop);
  EXPECT_EQ(status, kExitSuccess) << err.str();
  EXPECT_THAT(out.str(),
              HasSubstr("'camera' in 'base'\n  translation (m)    [0.000, 0.000, 2.000]"));
}

// Printed, as it is, but no pose a caller of --once can use.
TEST(Echo, ATranslationTooFarToAddUpIsSaidToBeNotFiniteAndOnceExitsOne) {
  const std::string url = lcmtf_test::privateUdpmUrl("Echo.ATranslationTooFarToAddUp");
  StaticTransformBroadcaster broadcaster(resendingOften(url));
  const Transform far({1e308, 0.0, 0.0}, {1, 0, 0, 0});
  broadcaster.sendTransform({{kStamp, "a", "b", far}, {kStamp, "b", "c", far}});

  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status =
      echoCommand({"--lcm-url", url, "--once", "--timeout", "10", "a", "c"}, out, err, stop);
  EXPECT_EQ(status, kExitFailure) << err.str();
  EXPECT_THAT(out.str(), HasSubstr("translation (m)    [inf, 0.000, 0.000]"));
  EXPECT_THAT(err.str(), HasSubstr("lcmtf-echo: the translation is not finite: the edges between "
                                   "'a' and 'c' are each finite but too far to add up"));
}

// A sender whose clock runs a minute ahead of this one: lcmtf-echo says why it refuses its
// transforms, and prints the pose once told to take any stamp.
TEST(Echo, TransformsStampedAMinuteAheadAreRefusedSayingWhyUnlessTheLimitIsLifted) {
  const std::string url = lcmtf_test::privateUdpmUrl("Echo.TransformsStampedAMinuteAhead");
  const lcmtf_test::ClockAheadSender sender(url);
  const std::atomic<bool> stop{false};
  std::ostringstream out, err;
  EXPECT_EQ(
      echoCommand({"--lcm-url", url, "--once", "--timeout", "1", "odom", "base"}, out, err, stop),
      kExitFailure);
  EXPECT_EQ(out.str(), "");
  EXPECT_THAT(err.str(), HasSubstr("refused transforms stamped more than 10.000000 s ahead of "
                                   "this machine's clock (first: 'odom' -> 'base' from "
                                   "'clock_ahead'"));
  EXPECT_THAT(err.str(), HasSubstr("gave up after 1.000000 s: frame 'odom' and frame 'base' are "
                                   "unknown; frames heard so far: none ("));
  EXPECT_THAT(err.str(), HasSubstr("refused as stamped more than 10.000000 s ahead of this "
                                   "machine's clock: synchronize the clocks, or take them with "
                                   "--max-stamp-ahead 0)"));
  std::ostringstream lifted_out, lifted_err;
  EXPECT_EQ(echoCommand({"--lcm-url", url, "--once", "--timeout", "10", "--max-stamp-ahead", "0",
                         "odom", "base"},
                        lifted_out, lifted_err, stop),
            kExitSuccess)
      << lifted_err.str();
  EXPECT_THAT(lifted_out.str(), HasSubstr("'base' in 'odom'"));
}

TEST(Echo, RunGivesUpAfterTheTimeoutSayingWhatIsMissing) {
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status = echoCommand(
      {"--lcm-url", "memq://", "--timeout", "0.2", "--rate", "20", "map", "base"}, out, err, stop);
  EXPECT_EQ(status, kExitFailure);
  EXPECT_EQ(out.str(), "");
  EXPECT_THAT(err.str(), HasSubstr("Waiting: no transforms received yet on TF or TF_STATIC at "
                                   "memq://"));
  EXPECT_THAT(err.str(), HasSubstr("lcmtf-echo: gave up after 0.200000 s: no transforms received"));
}

TEST(Echo, WaitingIsSaidAtMostOnceASecondAtAHighRate) {
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const int status = echoCommand(
      {"--lcm-url", "memq://", "--timeout", "1.5", "--rate", "200", "map", "base"}, out, err, stop);
  EXPECT_EQ(status, kExitFailure);
  std::size_t waiting = 0;
  for (std::size_t at = err.str().find("Waiting:"); at != std::string::npos;
       at = err.str().find("Waiting:", at + 1)) {
    ++waiting;
  }
  EXPECT_GE(waiting, 1u);
  EXPECT_LE(waiting, 2u) << err.str();
}

TEST(Echo, OnceStoppedBeforeAnyPoseExitsOneSayingSo) {
  std::ostringstream out, err;
  std::atomic<bool> stop{false};
  std::thread stopper([&stop] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    stop = true;
  });
  const int status = echoCommand({"--lcm-url", "memq://", "--once", "map", "base"}, out, err, stop);
  stopper.join();
  EXPECT_EQ(status, kExitFailure);
  EXPECT_THAT(err.str(),
              HasSubstr("lcmtf-echo: stopped before 'base' in 'map' could be looked up"));
}

// Publishes odom -> base on TF every 20 ms, stamped with the time it is sent, until stopped.
class MovingBase {
 public:
  explicit MovingBase(const std::string& url)
      : thread_([this, url] {
          TransformBroadcaster broadcaster(url, kTfChannel, "odometry");
          while (!stop_) {
            broadcaster.sendTransform({now(), "odom", "base", Transform()});
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
          }
        }) {}
  ~MovingBase() { stop(); }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

TEST(Echo, OnceAtAnInstantOlderThanAnyHistoryFailsAtOnce) {
  const std::string url =
      lcmtf_test::privateUdpmUrl("Echo.OnceAtAnInstantOlderThanAnyHistoryFailsAtOnce");
  MovingBase base(url);
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const auto start = std::chrono::steady_clock::now();
  const int status = echoCommand({"--lcm-url", url, "--once", "--timeout", "30", "--time",
                                  toString(now() - std::chrono::seconds(60)), "odom", "base"},
                                 out, err, stop);
  EXPECT_EQ(status, kExitFailure);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_THAT(err.str(), HasSubstr("can never be looked up: it is older than the 10.000000 s of "
                                   "history kept"));
  EXPECT_EQ(out.str(), "");
}

TEST(Echo, OnceBeforeNowWaitsUntilItsHistoryReachesThatFarBack) {
  const std::string url =
      lcmtf_test::privateUdpmUrl("Echo.OnceBeforeNowWaitsUntilItsHistoryReachesThatFarBack");
  MovingBase base(url);
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(
      echoCommand({"--lcm-url", url, "--once", "--time", "-0.5", "odom", "base"}, out, err, stop),
      kExitSuccess)
      << err.str();
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(400));
  EXPECT_THAT(out.str(), HasSubstr("'base' in 'odom'"));
}

TEST(Echo, ATimeoutShorterThanTheTimeBeforeNowIsSaidToBe) {
  const std::string url =
      lcmtf_test::privateUdpmUrl("Echo.ATimeoutShorterThanTheTimeBeforeNowIsSaidToBe");
  MovingBase base(url);
  std::ostringstream out, err;
  const std::atomic<bool> stop{false};
  EXPECT_EQ(
      echoCommand({"--lcm-url", url, "--once", "--time", "-20", "--timeout", "0.3", "odom", "base"},
                  out, err, stop),
      kExitFailure);
  EXPECT_THAT(err.str(), HasSubstr("history begins when lcmtf-echo starts listening: a moving "
                                   "frame's pose 20.000000 s ago needs a --timeout longer"));
}

TEST(Echo, WarnsOnceWhenTheLatestDataStopsChanging) {
  const std::string url =
      lcmtf_test::privateUdpmUrl("Echo.WarnsOnceWhenTheLatestDataStopsChanging");
  MovingBase base(url);
  std::ostringstream out, err;
  std::atomic<bool> stop{false};
  std::thread echo([&] {
    echoCommand({"--lcm-url", url, "--rate", "10", "odom", "base"}, out, err, stop);
  });
  Buffer heard;
  ListenerOptions listening;
  listening.lcm_url = url;
  const TransformListener listener(heard, listening);
  EXPECT_TRUE(heard.canTransform("odom", "base", kLatestTime, std::chrono::seconds(10)));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  base.stop();
  std::this_thread::sleep_for(std::chrono::milliseconds(3000));
  stop = true;
  echo.join();
  EXPECT_THAT(out.str(), HasSubstr("'base' in 'odom'"));
  const std::string said = err.str();
  EXPECT_THAT(said, HasSubstr("lcmtf-echo: warning: no new data for 'base' in 'odom' for "));
  EXPECT_THAT(said, HasSubstr("are its publishers still running?"));
  EXPECT_EQ(said.find("warning"), said.rfind("warning")) << "said once: " << said;
}

}  // namespace
}  // namespace lcmtf::nodes
