// The listener and the broadcasters across real processes over udpm (ttl=0, a port of each
// test's own), through lossy and reordered delivery, and through log replay.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/buffer.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf/wire_decode.hpp"
#include "support/buffer_core_helpers.hpp"
#include "support/child_process.hpp"
#include "support/sample_messages.hpp"
#include "support/test_lcm.hpp"
#include "support/transport_motion.hpp"

namespace lcmtf {
namespace {

using namespace std::chrono_literals;
using lcmtf_test::ChildProcess;
using lcmtf_test::near;
using lcmtf_test::odomTBase;
using testing::UnorderedElementsAre;

// Lerp and slerp of the peer's motion are exact; this leaves room for rounding only.
constexpr double kExact = 1e-9;
constexpr double kRounding = 1e-14;

std::string testUrl() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return lcmtf_test::privateUdpmUrl(std::string(info->test_suite_name()) + "." + info->name());
}

ListenerOptions onUrl(const std::string& url) {
  ListenerOptions options;
  options.lcm_url = url;
  return options;
}

// Arguments of a dynamic transport_peer: 100 Hz of odomTBase(stamp, origin, speed).
std::vector<std::string> dynamicPeer(const std::string& url, TimePoint origin, double speed,
                                     int duration_ms = 20000) {
  return {"dynamic",
          url,
          "100",
          std::to_string(duration_ms),
          std::to_string(toUtime(origin)),
          std::to_string(speed)};
}

// base_T_frame through the peer's static tree.
Transform baseT(const std::string& frame) {
  if (frame == "base") return Transform::identity();
  for (const TransformStamped& edge : lcmtf_test::peerStatics()) {
    if (edge.child_frame == frame) return baseT(edge.parent_frame) * edge.transform;
  }
  throw std::invalid_argument("not a static frame of the peer: " + frame);
}

// Handles `lcm` until `done` says so or `timeout` runs out; whether `done` said so.
bool handleUntil(lcm::LCM& lcm, const std::function<bool()>& done,
                 std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    lcm.handleTimeout(20);
  }
  return true;
}

void handleFor(lcm::LCM& lcm, std::chrono::milliseconds duration) {
  handleUntil(
      lcm, [] { return false; }, duration);
}

// For what another thread updates (a listener's statistics): checks every few milliseconds.
bool eventually(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(5ms);
  }
  return true;
}

struct MessageCounter {
  void onMessage(const lcm::ReceiveBuffer* /*buffer*/, const std::string& /*channel*/) { ++count; }
  int count = 0;
};

TEST(TransportProcess, ListenerLookupsEqualTheMotionABroadcasterProcessSends) {
  const std::string url = testUrl();
  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));
  const TimePoint origin = now();
  ChildProcess dynamic(TRANSPORT_PEER, dynamicPeer(url, origin, 1.0));
  ChildProcess statics(TRANSPORT_PEER, {"static", url});

  std::string why;
  ASSERT_TRUE(buffer.canTransform("odom", "base", kLatestTime, 5s, &why)) << why;
  const TimePoint first = buffer.getLatestCommonTime("odom", "base");
  ASSERT_TRUE(buffer.canTransform("odom", "camera_optical", first + 300ms, 5s, &why)) << why;

  for (int k = 0; k < 30; ++k) {  // 10.007 ms apart: between the 100 Hz samples, seldom on one
    const TimePoint t = first + Duration(k * 10'007);
    const Transform expected = odomTBase(t, origin, 1.0);
    const TransformStamped odom_base = buffer.lookupTransform("odom", "base", t);
    EXPECT_EQ(odom_base.stamp, t);
    EXPECT_TRUE(near(odom_base.transform, expected, kExact)) << "at " << toString(t);
    EXPECT_TRUE(near(buffer.lookupTransform("odom", "camera_optical", t).transform,
                     expected * baseT("camera_optical"), kExact))
        << "at " << toString(t);
    EXPECT_TRUE(near(buffer.lookupTransform("lidar", "odom", t).transform,
                     (expected * baseT("lidar")).inverse(), kExact))
        << "at " << toString(t);
  }
  const TransformStamped latest = buffer.lookupTransform("odom", "base", kLatestTime);
  EXPECT_GE(latest.stamp, first + 300ms);
  EXPECT_TRUE(near(latest.transform, odomTBase(latest.stamp, origin, 1.0), kExact));

  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.malformed, 0u);
  EXPECT_EQ(stats.rejected_transforms, 0u);
  EXPECT_EQ(stats.stale_batches, 0u);
}

TEST(TransportProcess, LateJoinerGetsTheStaticTreeThroughItsRequest) {
  const std::string url = testUrl();
  // Hear the peer's one publication at start, so the listener below joins after it for sure.
  auto probe = std::make_unique<lcm::LCM>(url);
  ASSERT_TRUE(probe->good()) << url;
  MessageCounter heard;
  probe->subscribe(kTfStaticChannel, &MessageCounter::onMessage, &heard);
  ChildProcess statics(TRANSPORT_PEER, {"static", url, "--no-resend"});
  ASSERT_TRUE(handleUntil(
      *probe, [&] { return heard.count > 0; }, 5s))
      << "the static peer never published on " << url;
  probe.reset();
  std::this_thread::sleep_for(300ms);

  // With resending off, only the answer to the listener's request can deliver the set now.
  const auto start = std::chrono::steady_clock::now();
  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));
  std::string why;
  ASSERT_TRUE(buffer.canTransform("camera_optical", "lidar", kLatestTime, 5s, &why)) << why;
  const double elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[ measured ] late joiner had the static tree " << elapsed_ms
            << " ms after its listener was created\n";
  RecordProperty("late_joiner_ms", std::to_string(elapsed_ms));

  for (const TransformStamped& edge : lcmtf_test::peerStatics()) {
    const TransformStamped got =
        buffer.lookupTransform(edge.parent_frame, edge.child_frame, kLatestTime);
    EXPECT_EQ(got.stamp, kLatestTime);
    EXPECT_TRUE(near(got.transform, edge.transform, 1e-12)) << edge.child_frame;
  }
}

TEST(TransportProcess, ListenerFollowsABroadcasterThatRestarts) {
  const std::string url = testUrl();
  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));
  const TimePoint origin = now();
  auto peer = std::make_unique<ChildProcess>(TRANSPORT_PEER, dynamicPeer(url, origin, 1.0));
  std::string why;
  ASSERT_TRUE(buffer.canTransform("odom", "base", kLatestTime, 5s, &why)) << why;
  const TransformStamped before = buffer.lookupTransform("odom", "base", kLatestTime);
  EXPECT_TRUE(near(before.transform, odomTBase(before.stamp, origin, 1.0), kExact));

  peer->kill();
  const TimePoint restarted = now();  // every sample of the first peer is older
  peer = std::make_unique<ChildProcess>(TRANSPORT_PEER, dynamicPeer(url, origin, -2.0));
  ASSERT_TRUE(buffer.canTransform("odom", "base", restarted, 5s, &why))
      << "nothing from the restarted broadcaster: " << why;
  const TimePoint first_new = buffer.getLatestCommonTime("odom", "base");
  ASSERT_TRUE(buffer.canTransform("odom", "base", first_new + 100ms, 5s, &why)) << why;

  const TransformStamped latest = buffer.lookupTransform("odom", "base", kLatestTime);
  EXPECT_GE(latest.stamp, first_new + 100ms);
  EXPECT_TRUE(near(latest.transform, odomTBase(latest.stamp, origin, -2.0), kExact));
  for (int k = 0; k < 10; ++k) {
    const TimePoint t = first_new + Duration(k * 10'007);
    EXPECT_TRUE(near(buffer.lookupTransform("odom", "base", t).transform,
                     odomTBase(t, origin, -2.0), kExact))
        << "at " << toString(t);
  }
  // The dead broadcaster's history is still there for lookups in its time.
  EXPECT_TRUE(near(buffer.lookupTransform("odom", "base", before.stamp).transform,
                   odomTBase(before.stamp, origin, 1.0), kExact));
  EXPECT_EQ(listener.statistics().stale_batches, 0u);
  EXPECT_EQ(listener.statistics().history_resets, 0u);
}

// A smooth, curved motion for the lossy-delivery test: |p''| <= 2.47 and |theta''| <= 0.5 about
// a fixed axis, so lerp and slerp between samples h seconds apart stray by at most h^2/8 * 2.5
// (metres, and radians, which bound every rotation-matrix entry's error).
const TimePoint kCurveOrigin = lcmtf_test::kEpoch;
Transform curvedMotion(TimePoint t) {
  const double s = toSeconds(t - kCurveOrigin);
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  return Transform(Eigen::Vector3d(std::sin(1.5 * s), std::cos(s), 0.1 * s),
                   Eigen::Quaterniond(Eigen::AngleAxisd(0.8 * s + 0.5 * std::sin(s), axis)));
}
double interpolationTolerance(std::int64_t gap_us) {
  const double h = static_cast<double>(gap_us) * 1e-6;
  return h * h / 8.0 * 2.5 + 1e-9;
}

TEST(TransportProcess, DroppedAndReorderedBatchesStillInterpolateWithinTolerance) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  std::mt19937 random(2024);
  std::bernoulli_distribution drop(0.2);
  std::uniform_int_distribution<std::int64_t> jitter(-2000, 2000);

  std::vector<std::int64_t> kept;     // in sending order
  std::vector<std::int64_t> dropped;  // never sent
  for (int i = 0; i < 300; ++i) {     // 3 s at 100 Hz, stamps jittered by up to 2 ms
    const std::int64_t stamp = toUtime(kCurveOrigin + 10s) + i * 10'000 + jitter(random);
    (drop(random) ? dropped : kept).push_back(stamp);
  }
  for (std::size_t window = 0; window < kept.size(); window += 5) {
    const auto begin = kept.begin() + static_cast<std::ptrdiff_t>(window);
    std::shuffle(begin, begin + std::min<std::ptrdiff_t>(5, kept.end() - begin), random);
  }
  ASSERT_FALSE(std::is_sorted(kept.begin(), kept.end()));
  ASSERT_GT(dropped.size(), 40u);

  for (const std::int64_t stamp : kept) {
    const TransformStamped sample{fromUtime(stamp), "odom", "base", curvedMotion(fromUtime(stamp))};
    const std::vector<std::uint8_t> bytes = lcmtf_test::encode(makeTfMessage({sample}, "lossy"));
    listener.handleMessage(bytes.data(), bytes.size(), kTfChannel);
  }
  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.messages, kept.size());
  EXPECT_EQ(stats.transforms, kept.size());
  EXPECT_EQ(stats.stale_batches, 0u);
  EXPECT_EQ(stats.rejected_transforms, 0u);

  std::vector<std::int64_t> sorted = kept;
  std::sort(sorted.begin(), sorted.end());
  std::int64_t widest_gap = 0;
  const auto check = [&](std::int64_t t) {
    const auto after = std::lower_bound(sorted.begin(), sorted.end(), t);
    const std::int64_t gap = *after == t ? 0 : *after - *std::prev(after);
    widest_gap = std::max(widest_gap, gap);
    const TransformStamped got = buffer.lookupTransform("odom", "base", fromUtime(t));
    ASSERT_EQ(toUtime(got.stamp), t);
    ASSERT_TRUE(near(got.transform, curvedMotion(fromUtime(t)), interpolationTolerance(gap)))
        << "at " << t << " between samples " << gap << " us apart";
  };
  for (const std::int64_t t : sorted) check(t);  // on a sample: that sample
  for (const std::int64_t t : dropped) {         // where a sample was lost: across the hole
    if (t > sorted.front() && t < sorted.back()) check(t);
  }
  std::uniform_int_distribution<std::int64_t> anywhere(sorted.front(), sorted.back());
  for (int i = 0; i < 1000; ++i) check(anywhere(random));
  EXPECT_GE(widest_gap, 20'000) << "no query fell across a dropped batch";
}

// The wire carries any int64 as a stamp; arithmetic on stamps near the ends of the range must
// neither overflow (a hang, or a jump back seen where there is none) nor stop the listener.
// With the largest limit on stamps ahead of the clock, which saturates, every stamp is taken.
TEST(TransportProcess, StampsAtTheEndsOfTheInt64RangeNeitherHangNorLookLikeAJumpBack) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.max_stamp_ahead = Duration::max();
  TransformListener listener(buffer, lcm, options);
  const auto send = [&](std::int64_t stamp) {
    const TransformStamped sample{fromUtime(stamp), "map", "far", Transform::identity()};
    const std::vector<std::uint8_t> bytes = lcmtf_test::encode(makeTfMessage({sample}, "edge"));
    listener.handleMessage(bytes.data(), bytes.size(), kTfChannel);
  };
  using Limits = std::numeric_limits<std::int64_t>;
  for (const std::int64_t stamp :
       {Limits::min(), Limits::min() + 1, std::int64_t{1}, Limits::max()}) {
    send(stamp);
    EXPECT_EQ(toUtime(buffer.getLatestCommonTime("map", "far")), stamp);
    EXPECT_TRUE(buffer.canTransform("far", "map", fromUtime(stamp)));
    const std::int64_t elsewhere = stamp < 0 ? stamp + 1'000'000'000 : stamp - 1'000'000'000;
    EXPECT_FALSE(buffer.canTransform("map", "far", fromUtime(elsewhere)));
  }
  EXPECT_EQ(listener.statistics().stale_batches, 0u);
  EXPECT_EQ(listener.statistics().transforms, 4u);

  for (int i = 0; i < 3; ++i) send(1);  // a real jump back: two dropped, then a reset
  EXPECT_EQ(listener.statistics().stale_batches, 2u);
  EXPECT_EQ(listener.statistics().history_resets, 1u);
  EXPECT_EQ(toUtime(buffer.getLatestCommonTime("map", "far")), 1);
}

TEST(TransportProcess, TheLargestStampsAreRefusedAsAheadOfTheClockByDefault) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  std::vector<std::string> reports;
  options.reporter = [&](const std::string& message) { reports.push_back(message); };
  TransformListener listener(buffer, lcm, options);
  using Limits = std::numeric_limits<std::int64_t>;
  for (const std::int64_t stamp : {Limits::max(), Limits::max() - 1}) {
    const TransformStamped sample{fromUtime(stamp), "map", "far", Transform::identity()};
    const std::vector<std::uint8_t> bytes = lcmtf_test::encode(makeTfMessage({sample}, "edge"));
    listener.handleMessage(bytes.data(), bytes.size(), kTfChannel);
  }
  EXPECT_EQ(listener.statistics().stamped_ahead, 2u);
  EXPECT_EQ(listener.statistics().transforms, 0u);
  EXPECT_FALSE(buffer.frameExists("far"));
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_NE(reports[0].find("at 9223372036854.775807"), std::string::npos) << reports[0];
}

// An lcm-logger of our own: writes every message it hears to a log file, and keeps the stamps
// of the TF batches.
class Recorder {
 public:
  explicit Recorder(const std::string& path) : log_(std::make_unique<lcm::LogFile>(path, "w")) {}
  bool good() const { return log_->good(); }
  void close() { log_.reset(); }
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    lcm::LogEvent event;
    event.eventnum = 0;  // LogFile numbers the events itself
    event.timestamp = buffer->recv_utime;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(buffer->data_size);
    event.data = buffer->data;
    if (log_->writeEvent(&event) != 0) ++write_errors;
    tf_message_t batch;
    if (channel == kTfChannel && decodeMessage(buffer->data, buffer->data_size, batch).ok) {
      for (const transform_t& t : batch.transforms) tf_stamps.push_back(t.utime);
    }
  }
  std::vector<std::int64_t> tf_stamps;
  int write_errors = 0;

 private:
  std::unique_ptr<lcm::LogFile> log_;
};

// One pass of a log through LCM's file provider, as fast as it reads, into `buffer` through a
// listener attached to that LCM.
class LogReplay {
 public:
  LogReplay(const std::string& path, Buffer& buffer)
      : lcm_("file://" + path + "?speed=0"), listener_(buffer, lcm_) {
    lcm_.subscribe(kTfChannel, &LogReplay::onTf, this);
  }
  // Replays until `tf_batches` TF batches have gone by in all; false when the log ended first.
  bool replayUntil(std::size_t tf_batches) {
    for (int bound = 0; bound < 100000 && tf_batches_ < tf_batches; ++bound) {
      if (lcm_.handleTimeout(1000) < 0) return false;  // LCM 1.3.1 says -1 at the end of a log
    }
    return tf_batches_ >= tf_batches;
  }
  bool replayToTheEnd() { return !replayUntil(std::numeric_limits<std::size_t>::max()); }
  std::size_t tfBatches() const { return tf_batches_; }
  const TransformListener& listener() const { return listener_; }

 private:
  void onTf(const lcm::ReceiveBuffer* /*buffer*/, const std::string& /*channel*/) { ++tf_batches_; }
  lcm::LCM lcm_;
  TransformListener listener_;
  std::size_t tf_batches_ = 0;
};

class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "lcmtf_test_XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Lookups of odom -> base and odom -> camera_optical at each stamp give the same answers, to
// rounding: while a rebuild of the replayed buffer's paths waits its turn after the jump back,
// its lookups walk the tree, which composes the static chain edge by edge in another order.
void expectSameLookups(const Buffer& replayed, const Buffer& live,
                       const std::vector<TimePoint>& stamps, const std::string& when) {
  for (const TimePoint t : stamps) {
    for (const char* frame : {"base", "camera_optical"}) {
      const TransformStamped expected = live.lookupTransform("odom", frame, t);
      std::string why;
      ASSERT_TRUE(replayed.canTransform("odom", frame, t, &why)) << when << ": " << why;
      const TransformStamped got = replayed.lookupTransform("odom", frame, t);
      EXPECT_EQ(got.stamp, expected.stamp) << when;
      EXPECT_TRUE(near(got.transform, expected.transform, kRounding))
          << when << ", odom -> " << frame << " at " << toString(t);
    }
  }
}

// `count` stamps going back from `newest` by a step that falls between samples.
std::vector<TimePoint> stampsBackFrom(std::int64_t newest, int count) {
  std::vector<TimePoint> stamps;
  for (int k = 0; k < count; ++k) stamps.push_back(fromUtime(newest - k * 13'337));
  return stamps;
}

TEST(TransportProcess, RecordedLogReplaysTwiceIntoOneBufferLikeLive) {
  TemporaryDirectory directory;
  const std::string path = (directory.path() / "tf.lcmlog").string();
  const std::string url = testUrl();
  const TimePoint origin = now();

  // Record ~1.5 s of a live stream, the static tree first, while a live listener looks on.
  Buffer live;
  Recorder recorder(path);
  ASSERT_TRUE(recorder.good()) << path;
  {
    lcm::LCM lcm(url);
    ASSERT_TRUE(lcm.good()) << url;
    lcm.subscribe(".*", &Recorder::onMessage, &recorder);
    TransformListener listener(live, lcm);
    ChildProcess statics(TRANSPORT_PEER, {"static", url, "--no-resend"});
    auto next_request = std::chrono::steady_clock::now() + 500ms;
    ASSERT_TRUE(handleUntil(
        lcm,
        [&] {
          if (std::chrono::steady_clock::now() > next_request) {  // in case the peer was not up
            listener.requestStatics();
            next_request += 500ms;
          }
          return live.canTransform("base", "camera_optical", kLatestTime);
        },
        5s));
    ChildProcess dynamic(TRANSPORT_PEER, dynamicPeer(url, origin, 1.0, 1500));
    ASSERT_TRUE(handleUntil(
        lcm, [&] { return dynamic.waitForExit(0ms).has_value(); }, 10s));
    handleFor(lcm, 100ms);  // what is still on its way
  }
  recorder.close();
  ASSERT_EQ(recorder.write_errors, 0);
  const std::vector<std::int64_t>& recorded = recorder.tf_stamps;
  ASSERT_GE(recorded.size(), 100u);
  ASSERT_TRUE(std::is_sorted(recorded.begin(), recorded.end()));
  const std::vector<TimePoint> final_stamps = stampsBackFrom(recorded.back(), 30);  // 0.39 s
  for (const TimePoint t : final_stamps) {
    ASSERT_TRUE(
        near(live.lookupTransform("odom", "base", t).transform, odomTBase(t, origin, 1.0), kExact));
  }

  // Half a second of history: the second pass starts ~1.5 s behind where the first ended.
  Buffer replayed(500ms);
  {
    LogReplay pass(path, replayed);
    ASSERT_TRUE(pass.replayToTheEnd());
    EXPECT_EQ(pass.tfBatches(), recorded.size());
    const ListenerStatistics stats = pass.listener().statistics();
    EXPECT_EQ(stats.history_resets, 0u);
    EXPECT_EQ(stats.stale_batches, 0u);
    EXPECT_EQ(stats.rejected_transforms, 0u);
    EXPECT_EQ(stats.malformed, 0u);
    expectSameLookups(replayed, live, final_stamps, "first pass");
  }
  {
    LogReplay pass(path, replayed);
    const std::size_t half = recorded.size() / 2;
    ASSERT_TRUE(pass.replayUntil(half));
    // Mid-way, lookups follow the replay, not what the first pass left behind: the jump back
    // cleared the dynamic history after two dropped batches.
    EXPECT_EQ(replayed.getLatestCommonTime("odom", "base"), fromUtime(recorded[half - 1]));
    expectSameLookups(replayed, live, stampsBackFrom(recorded[half - 1], 20), "mid second pass");

    ASSERT_TRUE(pass.replayToTheEnd());
    EXPECT_EQ(pass.tfBatches(), recorded.size());
    const ListenerStatistics stats = pass.listener().statistics();
    EXPECT_EQ(stats.history_resets, 1u);
    EXPECT_EQ(stats.stale_batches, 2u);
    EXPECT_EQ(stats.rejected_transforms, 0u);
    EXPECT_EQ(stats.malformed, 0u);
    expectSameLookups(replayed, live, final_stamps, "second pass");
  }
  EXPECT_TRUE(near(replayed.lookupTransform("base", "camera_optical", kLatestTime).transform,
                   baseT("camera_optical"), 1e-12))
      << "the static tree did not survive the reset";
}

void putInt32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::int32_t value) {
  const auto bits = static_cast<std::uint32_t>(value);
  for (std::size_t i = 0; i < 4; ++i) {
    bytes[offset + i] = static_cast<std::uint8_t>(bits >> (24 - 8 * i));
  }
}

// An honest one-transform batch whose count field then claims `count` transforms.
std::vector<std::uint8_t> batchClaiming(std::int32_t count) {
  const tf_message_t batch = makeTfMessage(
      {TransformStamped{fromUtime(5'000'000), "map", "claimed", Transform::identity()}}, "liar");
  std::vector<std::uint8_t> bytes = lcmtf_test::encode(batch);
  // after the hash, utime, authority and sequence
  putInt32(bytes, 8 + 8 + 4 + batch.authority.size() + 1 + 8, count);
  return bytes;
}

TEST(TransportProcess, HostileMessagesOverUdpmAreRejectedAndCountedAndChangeNothing) {
  const std::string url = testUrl();
  Buffer buffer;
  TransformListener listener(buffer, onUrl(url));
  lcm::LCM sender(url);
  ASSERT_TRUE(sender.good()) << url;
  TransformBroadcaster honest(sender, kTfChannel, "honest");
  const auto edge = [](const std::string& parent, const std::string& child, std::int64_t utime,
                       const Eigen::Vector3d& translation,
                       const Eigen::Quaterniond& rotation = Eigen::Quaterniond::Identity()) {
    return TransformStamped{fromUtime(utime), parent, child, Transform(translation, rotation)};
  };
  ASSERT_TRUE(honest.sendTransform(edge("map", "odom", 1'000'000, {1, 0, 0})));
  std::string why;
  ASSERT_TRUE(buffer.canTransform("map", "odom", kLatestTime, 5s, &why)) << why;

  std::vector<std::vector<std::uint8_t>> hostile;
  hostile.push_back(batchClaiming(5'000'000));
  hostile.push_back(batchClaiming(std::numeric_limits<std::int32_t>::max()));
  hostile.push_back(batchClaiming(-1));
  {
    std::vector<std::uint8_t> bytes = batchClaiming(1);  // an authority string of 1 GiB
    putInt32(bytes, 16, 1 << 30);
    hostile.push_back(bytes);
  }
  hostile.push_back(lcmtf_test::encode(lcmtf_test::sampleJointState()));  // another type
  hostile.push_back({});                                                  // nothing at all
  {
    std::vector<std::uint8_t> bytes = batchClaiming(1);
    bytes.push_back(0);  // one byte too many
    hostile.push_back(bytes);
  }
  {
    tf_message_t batch = makeTfMessage({edge("map", "long", 2'000'000, {0, 0, 0})}, "liar");
    batch.authority = std::string(300, 'a');
    hostile.push_back(lcmtf_test::encode(batch));
    batch.authority = "liar";
    batch.transforms[0].parent_frame = std::string(100'000, 'p');  // several udpm fragments
    hostile.push_back(lcmtf_test::encode(batch));
  }
  for (const std::vector<std::uint8_t>& bytes : hostile) {
    ASSERT_EQ(sender.publish(kTfChannel, bytes.data(), static_cast<unsigned int>(bytes.size())), 0);
  }
  // Well-formed, but every transform except the last is bad.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ASSERT_TRUE(honest.sendTransform({
      edge("map", "nan", 2'000'000, {nan, 0, 0}),
      edge("map", "infinite", 2'000'000, {0, std::numeric_limits<double>::infinity(), 0}),
      edge("map", "zero_rotation", 2'000'000, {0, 0, 0}, Eigen::Quaterniond(0, 0, 0, 0)),
      edge("map", "long_rotation", 2'000'000, {0, 0, 0}, Eigen::Quaterniond(2, 0, 0, 0)),
      edge("map", "", 2'000'000, {0, 0, 0}),
      edge("map", "map", 2'000'000, {0, 0, 0}),
      edge("map", "good", 2'000'000, {0, 0, 3}),
  }));
  ASSERT_TRUE(honest.sendTransform(edge("map", "odom", 2'000'000, {2, 0, 0})));

  ASSERT_TRUE(eventually(
      [&] {
        const ListenerStatistics stats = listener.statistics();
        return stats.messages == 3 && stats.malformed == hostile.size();
      },
      5s))
      << "not everything arrived";
  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.malformed, hostile.size());
  EXPECT_EQ(stats.rejected_transforms, 6u);
  EXPECT_EQ(stats.transforms, 3u);
  EXPECT_THAT(buffer.getAllFrameNames(), UnorderedElementsAre("map", "odom", "good"));
  EXPECT_EQ(buffer.lookupTransform("map", "odom", fromUtime(1'000'000)).transform.translation.x(),
            1.0);
  EXPECT_EQ(buffer.lookupTransform("map", "odom", fromUtime(1'500'000)).transform.translation.x(),
            1.5);
  EXPECT_EQ(buffer.lookupTransform("map", "good", kLatestTime).transform.translation.z(), 3.0);
}

}  // namespace
}  // namespace lcmtf
