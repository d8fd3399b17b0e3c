#include "lcmtf/transform_listener.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <new>
#include <stdexcept>
#include <thread>

#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "support/sample_messages.hpp"
#include "support/test_lcm.hpp"

namespace lcmtf {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;
using testing::HasSubstr;

TransformStamped edge(const std::string& parent, const std::string& child, std::int64_t utime,
                      double x = 1.0) {
  return TransformStamped{fromUtime(utime), parent, child,
                          Transform(Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity())};
}

void drain(lcm::LCM& lcm) {
  while (lcm.handleTimeout(0) > 0) {
  }
}

// A batch as a sender of our own making numbers it, handed to the listener as if received.
void receive(TransformListener& listener, const std::string& authority, std::int64_t sequence,
             const std::vector<TransformStamped>& transforms, const std::string& channel) {
  tf_message_t batch = makeTfMessage(transforms, authority);
  batch.sequence = sequence;
  const std::vector<std::uint8_t> bytes = lcmtf_test::encode(batch);
  listener.handleMessage(bytes.data(), bytes.size(), channel);
}

AuthorityStatistics statisticsOf(const TransformListener& listener, const std::string& authority) {
  for (const AuthorityStatistics& statistics : listener.authorityStatistics()) {
    if (statistics.authority == authority) return statistics;
  }
  ADD_FAILURE() << "the listener does not follow '" << authority << "'";
  return {};
}

TEST(TransformListener, BroadcastTransformsReachTheBuffer) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  TransformBroadcaster broadcaster(lcm, kTfChannel, "test_broadcaster");
  ASSERT_TRUE(broadcaster.sendTransform(
      {edge("map", "odom", 1'000'000, 1.0), edge("odom", "base", 1'000'000, 2.0)}));
  drain(lcm);
  EXPECT_EQ(buffer.lookupTransform("map", "base", kLatestTime).transform.translation.x(), 3.0);
  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.messages, 1u);
  EXPECT_EQ(stats.transforms, 2u);
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("authority: 'test_broadcaster'"));
}

TEST(TransformListener, StaticBroadcasterAnswersTheListenersRequest) {
  lcm::LCM lcm("memq://");
  StaticBroadcasterOptions options;
  options.resend_period = Duration::zero();
  StaticTransformBroadcaster statics(lcm, options);
  statics.sendTransform({edge("base", "camera", 0, 0.5), edge("base", "lidar", 0, 0.25)});
  drain(lcm);  // nobody listens yet: this first publication is lost

  Buffer buffer;
  TransformListener listener(buffer, lcm);
  drain(lcm);
  EXPECT_EQ(statics.requestsAnswered(), 1u);
  EXPECT_EQ(buffer.lookupTransform("base", "camera", kLatestTime).transform.translation.x(), 0.5);
  EXPECT_EQ(toUtime(buffer.lookupTransform("camera", "lidar", kLatestTime).stamp), 0);
}

TEST(TransformListener, StaticSetIsKeyedByChildFrame) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  StaticTransformBroadcaster statics(lcm);
  statics.sendTransform(edge("base", "camera", 0, 0.5));
  statics.sendTransform(edge("base", "camera", 0, 0.75));
  statics.sendTransform(edge("base", "lidar", 0, 1.0));
  EXPECT_EQ(statics.size(), 2u);
  drain(lcm);
  EXPECT_EQ(buffer.lookupTransform("base", "camera", kLatestTime).transform.translation.x(), 0.75);
}

TEST(TransformListener, StaticOnlyModeIgnoresDynamicTransforms) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.static_only = true;
  TransformListener listener(buffer, lcm, options);
  TransformBroadcaster dynamic(lcm);
  TransformBroadcaster statics(lcm, kTfStaticChannel);
  dynamic.sendTransform(edge("map", "odom", 1'000'000));
  statics.sendTransform(edge("base", "camera", 0));
  drain(lcm);
  EXPECT_FALSE(buffer.frameExists("odom"));
  EXPECT_TRUE(buffer.canTransform("base", "camera", kLatestTime));
}

TEST(TransformListener, AllowListIgnoresOtherAuthorities) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.allowed_authorities = {"trusted"};
  TransformListener listener(buffer, lcm, options);
  TransformBroadcaster trusted(lcm, kTfChannel, "trusted");
  TransformBroadcaster intruder(lcm, kTfChannel, "intruder");
  trusted.sendTransform(edge("map", "odom", 1'000'000, 1.0));
  intruder.sendTransform(edge("map", "odom", 2'000'000, 99.0));
  drain(lcm);
  EXPECT_EQ(buffer.lookupTransform("map", "odom", kLatestTime).transform.translation.x(), 1.0);
  EXPECT_EQ(listener.statistics().unauthorized, 1u);
}

TEST(TransformListener, AuthorityConflictIsCountedAndShownInYaml) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  TransformBroadcaster first(lcm, kTfChannel, "first");
  TransformBroadcaster second(lcm, kTfChannel, "second");
  first.sendTransform(edge("map", "odom", 1'000'000));
  second.sendTransform(edge("map", "odom", 2'000'000));
  drain(lcm);
  EXPECT_EQ(buffer.statistics().authority_conflicts, 1u);
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("authority_conflicts: 1"));
}

TEST(TransformListener, MalformedMessagesAreCountedAndChangeNothing) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  TransformBroadcaster broadcaster(lcm);
  broadcaster.sendTransform(edge("map", "odom", 1'000'000, 1.0));

  std::vector<std::uint8_t> truncated = lcmtf_test::encode(lcmtf_test::sampleTfMessage(3));
  truncated.resize(truncated.size() - 5);
  lcm.publish(kTfChannel, truncated.data(), static_cast<unsigned int>(truncated.size()));
  const std::vector<std::uint8_t> garbage(64, 0x7f);
  lcm.publish(kTfChannel, garbage.data(), static_cast<unsigned int>(garbage.size()));

  tf_message_t huge = lcmtf_test::sampleTfMessage(1);
  huge.transforms[0].child_frame = std::string(300, 'x');
  lcm.publish(kTfChannel, &huge);
  drain(lcm);

  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.malformed, 3u);
  EXPECT_EQ(stats.messages, 1u);
  EXPECT_EQ(buffer.getAllFrameNames(), (std::vector<std::string>{"odom", "map"}));
  EXPECT_EQ(buffer.lookupTransform("map", "odom", kLatestTime).transform.translation.x(), 1.0);
}

TEST(TransformListener, FloodOfNewFrameNamesStopsAtTheCap) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.max_frames = 10;
  TransformListener listener(buffer, lcm, options);
  TransformBroadcaster broadcaster(lcm);
  std::vector<TransformStamped> flood;
  for (int i = 0; i < 100; ++i) flood.push_back(edge("map", "f" + std::to_string(i), 1'000'000));
  broadcaster.sendTransform(flood);
  broadcaster.sendTransform(edge("map", "f3", 2'000'000, 5.0));
  drain(lcm);
  EXPECT_EQ(buffer.frameCount(), 10u);
  EXPECT_EQ(listener.statistics().frame_limit, 91u);
  EXPECT_EQ(buffer.lookupTransform("map", "f3", kLatestTime).transform.translation.x(), 5.0);
}

// A batch too small to reach max_frames is stored without a look at its names; one that might
// reach it is checked name by name, and one that fills the frames left exactly is whole.
TEST(TransformListener, ABatchThatFillsTheFramesLeftExactlyIsStoredWhole) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.max_frames = 10;
  TransformListener listener(buffer, lcm, options);
  std::vector<TransformStamped> pairs;
  for (int i = 0; i < 5; ++i) {
    pairs.push_back(edge("p" + std::to_string(i), "c" + std::to_string(i), 1'000'000));
  }
  receive(listener, "sender", 1, pairs, kTfChannel);
  EXPECT_EQ(buffer.frameCount(), 10u);
  EXPECT_EQ(listener.statistics().frame_limit, 0u);

  receive(listener, "sender", 2,
          {edge("p0", "c0", 2'000'000, 4.0), edge("p5", "c5", 2'000'000),
           edge("c1", "c6", 2'000'000), edge("p1", "c1", 2'000'000, 6.0)},
          kTfChannel);
  EXPECT_EQ(buffer.frameCount(), 10u);
  EXPECT_EQ(listener.statistics().frame_limit, 2u);
  EXPECT_EQ(listener.statistics().transforms, 7u);
  EXPECT_EQ(buffer.lookupTransform("p0", "c0", kLatestTime).transform.translation.x(), 4.0);
  EXPECT_EQ(buffer.lookupTransform("p1", "c1", kLatestTime).transform.translation.x(), 6.0);
  EXPECT_FALSE(buffer.frameExists("c6"));

  // Six pairs of new frames are more than the ten left: the sixth is refused.
  Buffer fresh;
  TransformListener fresh_listener(fresh, lcm, options);
  pairs.push_back(edge("p5", "c5", 1'000'000));
  receive(fresh_listener, "sender", 1, pairs, kTfChannel);
  EXPECT_EQ(fresh.frameCount(), 10u);
  EXPECT_EQ(fresh_listener.statistics().frame_limit, 1u);
  EXPECT_FALSE(fresh.frameExists("c5"));
}

// Batches of every size, one after another, as several publishers on one channel send them:
// each is stored exactly, none keeping anything of a longer one before it.
TEST(TransformListener, BatchesOfChangingSizesAreEachStoredExactly) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  std::int64_t sequence = 0;
  std::size_t sent = 0;
  for (int size : {5, 1, 3, 0, 2, 5}) {
    ++sequence;
    std::vector<TransformStamped> batch;
    for (int i = 0; i < size; ++i) {
      batch.push_back(edge("map", "frame_with_a_long_name_" + std::to_string(i),
                           sequence * 1'000'000, 10.0 * static_cast<double>(sequence) + i));
    }
    receive(listener, "sender", sequence, batch, kTfChannel);
    sent += batch.size();
    for (int i = 0; i < size; ++i) {
      EXPECT_EQ(buffer
                    .lookupTransform("map", "frame_with_a_long_name_" + std::to_string(i),
                                     fromUtime(sequence * 1'000'000))
                    .transform.translation.x(),
                10.0 * static_cast<double>(sequence) + i);
    }
  }
  EXPECT_EQ(listener.statistics().transforms, sent);
  EXPECT_EQ(listener.statistics().rejected_transforms, 0u);
}

// A request's callback runs inside the insert of the batch that decided it; one that hands the
// listener another batch there gets that batch stored as well.
TEST(TransformListener, ABatchHandedInFromARequestCallbackIsStoredToo) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  int calls = 0;
  buffer.addTransformableRequest(
      [&](TransformableRequestHandle, const std::string&, const std::string&, TimePoint,
          TransformableResult result) {
        ++calls;
        EXPECT_EQ(result, TransformableResult::kAvailable);
        receive(listener, "inner", 1, {edge("map", "marker", 1'000'000, 4.0)}, kTfChannel);
      },
      "map", "base", fromUtime(1'000'000));
  receive(listener, "outer", 1,
          {edge("map", "odom", 1'000'000, 2.0), edge("odom", "base", 1'000'000, 3.0)}, kTfChannel);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(buffer.lookupTransform("map", "base", kLatestTime).transform.translation.x(), 5.0);
  EXPECT_EQ(buffer.lookupTransform("map", "marker", kLatestTime).transform.translation.x(), 4.0);
  EXPECT_EQ(listener.statistics().messages, 2u);
  EXPECT_EQ(listener.statistics().transforms, 3u);
}

// Messages handed to one listener from several threads at once (a replay beside the
// listener's own handling) are each stored whole.
TEST(TransformListenerConcurrency, MessagesHandedInFromSeveralThreadsAreEachStoredWhole) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  constexpr int kThreads = 3;
  constexpr int kBatches = 300;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&listener, t] {
      const std::string sender = "sender_" + std::to_string(t);
      for (int b = 1; b <= kBatches; ++b) {
        std::vector<TransformStamped> batch;
        for (int i = 0; i < 1 + b % 4; ++i) {
          batch.push_back(edge(sender + "_root", sender + "_frame_" + std::to_string(i), b * 10'000,
                               static_cast<double>(b)));
        }
        receive(listener, sender, b, batch, kTfChannel);
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  std::size_t expected = 0;
  for (int b = 1; b <= kBatches; ++b) expected += static_cast<std::size_t>(kThreads * (1 + b % 4));
  EXPECT_EQ(listener.statistics().transforms, expected);
  EXPECT_EQ(listener.statistics().messages, static_cast<std::uint64_t>(kThreads * kBatches));
  for (int t = 0; t < kThreads; ++t) {
    const std::string sender = "sender_" + std::to_string(t);
    EXPECT_EQ(
        buffer.lookupTransform(sender + "_root", sender + "_frame_0", fromUtime(kBatches * 10'000))
            .transform.translation.x(),
        static_cast<double>(kBatches));
  }
}

TEST(TransformListener, SingleStalePacketIsDroppedButASustainedJumpBackResetsHistory) {
  lcm::LCM lcm("memq://");
  Buffer buffer(std::chrono::seconds(1));
  TransformListener listener(buffer, lcm);
  TransformBroadcaster dynamic(lcm, kTfChannel, "replay");
  StaticTransformBroadcaster statics(lcm);
  statics.sendTransform(edge("base", "camera", 0));
  for (std::int64_t t = 50'000'000; t <= 60'000'000; t += 100'000) {
    dynamic.sendTransform(edge("odom", "base", t, 1.0));
  }
  dynamic.sendTransform(edge("odom", "base", 1'000'000, 7.0));  // one stale packet
  dynamic.sendTransform(edge("odom", "base", 60'100'000, 1.0));
  drain(lcm);
  EXPECT_EQ(listener.statistics().stale_batches, 1u);
  EXPECT_EQ(listener.statistics().history_resets, 0u);

  for (std::int64_t t = 1'000'000; t <= 1'500'000; t += 100'000) {
    dynamic.sendTransform(edge("odom", "base", t, 2.0));
  }
  drain(lcm);
  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.history_resets, 1u);
  EXPECT_EQ(stats.stale_batches, 3u);
  const TransformStamped after = buffer.lookupTransform("odom", "camera", kLatestTime);
  EXPECT_EQ(toUtime(after.stamp), 1'500'000);
  EXPECT_EQ(after.transform.translation.x(), 3.0);
}

// A made-up sender, four times a second, sends one batch stamped now and three stamped 20 s
// earlier. Its jump back clears only the edge it sent, once per cache time; the good tree's
// history and latest lookups never fail meanwhile.
TEST(TransformListener, ForgedJumpsBackClearOnlyTheForgersEdgesAtMostOncePerCacheTime) {
  lcm::LCM lcm("memq://");
  Buffer buffer;  // 10 s of history
  TransformListener listener(buffer, lcm);
  TransformBroadcaster good(lcm, kTfChannel, "odometry");
  TransformBroadcaster forger(lcm, kTfChannel, "forger");
  StaticTransformBroadcaster statics(lcm);
  statics.sendTransform(edge("base", "camera", 0));
  const std::int64_t start = toUtime(now());
  constexpr int kTicks = 125;  // 10 ms apart: five rounds of the forger
  std::size_t failed_lookups = 0;
  for (int tick = 0; tick < kTicks; ++tick) {
    const std::int64_t stamp = start + tick * 10'000;
    good.sendTransform(edge("odom", "base", stamp, 1.0 + tick));
    if (tick % 25 == 0) {
      forger.sendTransform(edge("odom", "forged", stamp));
      for (int old = 0; old < 3; ++old)
        forger.sendTransform(edge("odom", "forged", stamp - 20'000'000));
    }
    drain(lcm);
    for (const std::int64_t t : {stamp, start, (start + stamp) / 2}) {
      if (!buffer.canTransform("camera", "odom", fromUtime(t))) ++failed_lookups;
    }
    if (!buffer.canTransform("camera", "odom", kLatestTime)) ++failed_lookups;
    std::this_thread::sleep_for(milliseconds(10));
  }
  EXPECT_EQ(failed_lookups, 0u);
  EXPECT_EQ(buffer.lookupTransform("odom", "base", fromUtime(start)).transform.translation.x(),
            1.0);

  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.history_resets, 1u);
  EXPECT_EQ(stats.cleared_edges, 1u);
  EXPECT_EQ(stats.resets_held_back, 4u);  // the third old batch of each later round
  EXPECT_EQ(stats.stale_batches, 2u + 4u * 3u);
  const AuthorityStatistics forged = statisticsOf(listener, "forger");
  EXPECT_EQ(forged.history_resets, 1u);
  EXPECT_EQ(forged.cleared_edges, 1u);
  EXPECT_EQ(forged.resets_held_back, 4u);
  EXPECT_EQ(forged.batches, 20u);
  const AuthorityStatistics odometry = statisticsOf(listener, "odometry");
  EXPECT_EQ(odometry.history_resets, 0u);
  EXPECT_EQ(odometry.stale_batches, 0u);
  EXPECT_EQ(odometry.batches, static_cast<std::uint64_t>(kTicks));
}

TEST(TransformListener, ASenderMayResetAgainOnceTheCacheTimeHasPassed) {
  lcm::LCM lcm("memq://");
  Buffer buffer(milliseconds(100));
  std::vector<std::string> reports;
  ListenerOptions options;
  options.reporter = [&](const std::string& message) { reports.push_back(message); };
  TransformListener listener(buffer, lcm, options);
  TransformBroadcaster replay(lcm, kTfChannel, "replay");
  const auto playTwice = [&] {
    for (std::int64_t t = 5'000'000; t <= 5'050'000; t += 10'000) {
      replay.sendTransform(edge("odom", "base", t));
    }
    for (std::int64_t t = 1'000'000; t <= 1'030'000; t += 10'000) {
      replay.sendTransform(edge("odom", "base", t));
    }
    drain(lcm);
  };
  playTwice();
  std::this_thread::sleep_for(milliseconds(150));
  playTwice();
  EXPECT_EQ(listener.statistics().history_resets, 2u);
  EXPECT_EQ(listener.statistics().resets_held_back, 0u);
  EXPECT_EQ(toUtime(buffer.getLatestCommonTime("odom", "base")), 1'030'000);
  ASSERT_EQ(reports.size(), 1u) << "one report per sender";
  EXPECT_THAT(reports[0], HasSubstr("'replay'"));
  EXPECT_THAT(reports[0], HasSubstr("cleared the dynamic history of the 1 edges it sent last"));
}

ListenerOptions onMemq() {
  ListenerOptions options;
  options.lcm_url = "memq://";
  return options;
}

// A log of two senders played twice through one listener, beside a live sender: each sender of
// the log restarts its own edges; the live one's history stays whole.
TEST(TransformListener, LogPlayedAgainRestartsEachOfItsSendersAndSparesTheLiveOne) {
  Buffer buffer(seconds(1));
  TransformListener listener(buffer, onMemq());
  std::int64_t live_stamp = 100'000'000;
  std::size_t live_history_missing = 0;
  const auto play = [&] {
    std::int64_t sequence = 0;
    for (std::int64_t t = 50'000'000; t <= 53'000'000; t += 100'000) {
      ++sequence;
      receive(listener, "odometry", sequence, {edge("odom", "base", t, 1.0)}, kTfChannel);
      receive(listener, "arm", sequence, {edge("base", "hand", t, 2.0)}, kTfChannel);
      live_stamp += 100'000;
      receive(listener, "live", live_stamp / 100'000, {edge("world", "drone", live_stamp, 3.0)},
              kTfChannel);
      if (live_stamp > 100'900'000 &&
          !buffer.canTransform("world", "drone", fromUtime(live_stamp - 900'000))) {
        ++live_history_missing;
      }
    }
  };
  play();
  play();
  EXPECT_EQ(live_history_missing, 0u);
  EXPECT_EQ(toUtime(buffer.getLatestCommonTime("odom", "hand")), 53'000'000);
  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.history_resets, 2u);
  EXPECT_EQ(stats.cleared_edges, 2u);
  EXPECT_EQ(stats.stale_batches, 4u);
  EXPECT_EQ(stats.sequence_restarts, 2u);
  EXPECT_EQ(stats.lost_batches, 0u);
  EXPECT_EQ(stats.duplicated_batches, 0u);
  for (const char* sender : {"odometry", "arm"}) {
    const AuthorityStatistics replayed = statisticsOf(listener, sender);
    EXPECT_EQ(replayed.history_resets, 1u) << sender;
    EXPECT_EQ(replayed.cleared_edges, 1u) << sender;
    EXPECT_EQ(replayed.sequence_restarts, 1u) << sender;
  }
  EXPECT_EQ(statisticsOf(listener, "live").history_resets, 0u);
}

// 100,000 senders of one batch each: the listener follows at most max_authorities of them,
// forgets the least recently heard, and stores every batch of the sender it keeps hearing.
TEST(TransformListener, FloodOfNewAuthorityNamesKeepsTheListenerBoundedAndGoodBatchesStored) {
  Buffer buffer;
  ListenerOptions options;
  options.lcm_url = "memq://";
  options.max_authorities = 1000;
  TransformListener listener(buffer, options);
  constexpr int kFlood = 100'000;
  constexpr int kGoodEvery = 100;
  const std::int64_t start = 1'000'000'000;
  std::int64_t good_sequence = 0;
  for (int i = 0; i < kFlood; ++i) {
    const std::int64_t stamp = start + i * 10;
    receive(listener, "flood_" + std::to_string(i), 1, {edge("map", "flooded", stamp)}, kTfChannel);
    if (i % kGoodEvery == 0) {
      receive(listener, "odometry", ++good_sequence, {edge("odom", "base", stamp, 1.0)},
              kTfChannel);
    }
  }
  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.authorities_followed, 1000u);
  EXPECT_EQ(listener.authorityStatistics().size(), 1000u);
  EXPECT_EQ(stats.authorities_forgotten, kFlood + 1u - 1000u);
  EXPECT_EQ(stats.lost_batches, 0u);
  const AuthorityStatistics odometry = statisticsOf(listener, "odometry");
  EXPECT_EQ(odometry.batches, static_cast<std::uint64_t>(good_sequence));
  EXPECT_EQ(odometry.lost_batches, 0u);
  EXPECT_EQ(stats.messages, kFlood + static_cast<std::uint64_t>(good_sequence));
  for (std::int64_t k = 0; k < good_sequence; k += 37) {
    const std::int64_t stamp = start + k * kGoodEvery * 10;
    EXPECT_EQ(toUtime(buffer.lookupTransform("odom", "base", fromUtime(stamp)).stamp), stamp);
  }
}

// Between two batches of a sender it keeps hearing, 5,000 names used once each: the listener
// still follows that sender, so the batch lost in between is counted.
TEST(TransformListener, FloodOfNamesUsedOnceNeverMakesTheListenerForgetASenderItKeepsHearing) {
  Buffer buffer;
  ListenerOptions options = onMemq();
  options.max_authorities = 100;
  TransformListener listener(buffer, options);
  std::int64_t stamp = 1'000'000;
  receive(listener, "odometry", 1, {edge("odom", "base", ++stamp)}, kTfChannel);
  receive(listener, "odometry", 2, {edge("odom", "base", ++stamp)}, kTfChannel);
  for (int i = 0; i < 5000; ++i) {
    receive(listener, "flood_" + std::to_string(i), 1, {edge("map", "flooded", ++stamp)},
            kTfChannel);
  }
  receive(listener, "odometry", 4, {edge("odom", "base", ++stamp)}, kTfChannel);
  const AuthorityStatistics odometry = statisticsOf(listener, "odometry");
  EXPECT_EQ(odometry.batches, 3u);
  EXPECT_EQ(odometry.lost_batches, 1u);
  EXPECT_EQ(listener.authorityStatistics().front().authority, "odometry");
  EXPECT_EQ(listener.statistics().authorities_followed, 100u);
  EXPECT_EQ(listener.statistics().authorities_forgotten, 5000u - 99u);
}

// Per sender and channel: 1 2 5 4 4 6 loses 3 and 4, gets 4 back late, then 4 again.
TEST(TransformListener, SequenceGapsReordersAndDuplicatesAreCountedPerAuthorityAndChannel) {
  Buffer buffer;
  TransformListener listener(buffer, onMemq());
  std::int64_t stamp = 1'000'000;
  const auto send = [&](const std::string& authority, std::int64_t sequence,
                        const std::string& channel) {
    stamp += 1000;
    const bool dynamic = channel == kTfChannel;
    receive(listener, authority, sequence,
            {edge(authority, authority + (dynamic ? "_moving" : "_mounted"), dynamic ? stamp : 0)},
            channel);
  };
  for (std::int64_t n : {1, 2, 5, 4, 4, 6}) send("arm", n, kTfChannel);
  for (std::int64_t n : {1, 2, 3}) send("arm", n, kTfStaticChannel);            // numbered apart
  for (std::int64_t n : {10, 11, 13, 12, 14, 20}) send("base", n, kTfChannel);  // joined late
  for (std::int64_t n : {0, 0, 0}) send("legacy", n, kTfChannel);               // not numbered
  for (std::int64_t n : {40, 41, 1, 2, 4}) send("restarted", n, kTfChannel);

  const AuthorityStatistics arm = statisticsOf(listener, "arm");
  EXPECT_EQ(arm.batches, 9u);
  EXPECT_EQ(arm.lost_batches, 1u);
  EXPECT_EQ(arm.reordered_batches, 1u);
  EXPECT_EQ(arm.duplicated_batches, 1u);
  EXPECT_EQ(arm.sequence_restarts, 0u);
  const AuthorityStatistics base = statisticsOf(listener, "base");
  EXPECT_EQ(base.lost_batches, 5u);
  EXPECT_EQ(base.reordered_batches, 1u);
  EXPECT_EQ(base.duplicated_batches, 0u);
  const AuthorityStatistics legacy = statisticsOf(listener, "legacy");
  EXPECT_EQ(legacy.lost_batches + legacy.reordered_batches + legacy.duplicated_batches, 0u);
  const AuthorityStatistics restarted = statisticsOf(listener, "restarted");
  EXPECT_EQ(restarted.sequence_restarts, 1u);
  EXPECT_EQ(restarted.lost_batches, 1u);

  const ListenerStatistics stats = listener.statistics();
  EXPECT_EQ(stats.lost_batches, 7u);
  EXPECT_EQ(stats.reordered_batches, 2u);
  EXPECT_EQ(stats.duplicated_batches, 1u);
  EXPECT_EQ(stats.sequence_restarts, 1u);
  EXPECT_EQ(listener.authorityStatistics().front().authority, "restarted");  // heard last
}

TEST(TransformListener, BroadcastBatchesArriveNumberedWithNothingLost) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  TransformBroadcaster first(lcm, kTfChannel, "shared_name");
  TransformBroadcaster second(lcm, kTfChannel, "shared_name");  // one stream with the first
  StaticBroadcasterOptions static_options;
  static_options.authority = "shared_name";
  StaticTransformBroadcaster statics(lcm, static_options);
  for (int i = 1; i <= 10; ++i) {
    (i % 2 ? first : second).sendTransform(edge("odom", "base", i * 1000));
    statics.sendTransform(edge("base", "camera_" + std::to_string(i), 0));
  }
  drain(lcm);
  const AuthorityStatistics shared = statisticsOf(listener, "shared_name");
  EXPECT_GE(shared.batches, 20u);
  EXPECT_EQ(shared.lost_batches + shared.reordered_batches + shared.duplicated_batches +
                shared.sequence_restarts,
            0u);
}

TEST(TransformListener, ABatchMadeByHandIsNotNumberedWhateverTheMemoryHeldBefore) {
  alignas(tf_message_t) unsigned char storage[sizeof(tf_message_t)];
  std::memset(storage, 0xab, sizeof storage);
  // Built where it is returned to, so nothing but makeTfMessage sets its fields.
  auto* batch = new (storage) tf_message_t(makeTfMessage({edge("odom", "base", 1000)}, "hand"));
  EXPECT_EQ(batch->sequence, 0);
  Buffer buffer;
  lcm::LCM lcm("memq://");
  TransformListener listener(buffer, lcm);
  const std::vector<std::uint8_t> bytes = lcmtf_test::encode(*batch);
  for (int i = 0; i < 3; ++i) listener.handleMessage(bytes.data(), bytes.size(), kTfChannel);
  const AuthorityStatistics hand = statisticsOf(listener, "hand");
  EXPECT_EQ(hand.lost_batches + hand.duplicated_batches + hand.sequence_restarts, 0u);
  batch->~tf_message_t();
}

TEST(TransformListener, AMaximumInterpolationGapMakesLookupsAcrossLostBatchesFail) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.max_interpolation_gap = std::chrono::milliseconds(50);
  TransformListener listener(buffer, lcm, options);
  EXPECT_EQ(buffer.maxInterpolationGap(), std::chrono::milliseconds(50));
  TransformBroadcaster broadcaster(lcm, kTfChannel, "driver");
  for (const std::int64_t utime : {1'000'000, 1'010'000, 2'000'000}) {
    ASSERT_TRUE(broadcaster.sendTransform(
        {edge("odom", "base", utime, static_cast<double>(utime) * 1e-6)}));
  }
  drain(lcm);
  EXPECT_NEAR(
      buffer.lookupTransform("odom", "base", fromUtime(1'005'000)).transform.translation.x(), 1.005,
      1e-9);
  EXPECT_THROW(buffer.lookupTransform("odom", "base", fromUtime(1'500'000)),
               InterpolationGapException);
}

// A second sender of an edge, its clock an hour ahead (or a forger), sends it once: the sample
// is refused, and the edge keeps its history and the samples of its publisher.
TEST(TransformListener, ATransformStampedFarAheadOfTheClockIsRefusedAndTheEdgeKeepsItsPublisher) {
  lcm::LCM lcm("memq://");
  Buffer buffer;  // 10 s of history
  std::vector<std::string> reports;
  ListenerOptions options;
  options.reporter = [&](const std::string& message) { reports.push_back(message); };
  TransformListener listener(buffer, lcm, options);
  TransformBroadcaster odometry(lcm, kTfChannel, "odometry");
  TransformBroadcaster ahead(lcm, kTfChannel, "clock_ahead");
  const std::int64_t start = toUtime(now()) - 1'000'000;
  for (int i = 0; i < 100; ++i) odometry.sendTransform(edge("odom", "base", start + i * 10'000, i));
  ahead.sendTransform(edge("odom", "base", toUtime(now()) + 3'600'000'000, -999.0));
  for (int i = 100; i < 110; ++i)
    odometry.sendTransform(edge("odom", "base", start + i * 10'000, i));
  drain(lcm);

  const TransformStamped latest = buffer.lookupTransform("odom", "base", kLatestTime);
  EXPECT_EQ(toUtime(latest.stamp), start + 109 * 10'000);
  EXPECT_EQ(latest.transform.translation.x(), 109.0);
  EXPECT_EQ(buffer.lookupTransform("odom", "base", fromUtime(start)).transform.translation.x(),
            0.0);
  EXPECT_EQ(buffer.statistics().rejectedTotal(), 0u);
  EXPECT_EQ(listener.statistics().stamped_ahead, 1u);
  EXPECT_EQ(listener.statistics().transforms, 110u);
  EXPECT_EQ(statisticsOf(listener, "clock_ahead").stamped_ahead, 1u);
  EXPECT_EQ(statisticsOf(listener, "odometry").stamped_ahead, 0u);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr("'odom' -> 'base' from 'clock_ahead'"));
  EXPECT_THAT(reports[0], HasSubstr("more than 10.000000 s ahead of this machine's clock"));
  EXPECT_THAT(reports[0], HasSubstr("max_stamp_ahead"));
}

// What the limit prevents: stored, the sample an hour ahead becomes the edge's newest, its
// history goes, and the publisher's samples are refused as older than the history kept.
TEST(TransformListener, WithNoLimitOneTransformFarAheadMakesTheEdgeRefuseItsPublisher) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  buffer.setErrorReporter(nullptr);
  ListenerOptions options;
  options.max_stamp_ahead = Duration::zero();
  TransformListener listener(buffer, lcm, options);
  TransformBroadcaster odometry(lcm, kTfChannel, "odometry");
  TransformBroadcaster ahead(lcm, kTfChannel, "clock_ahead");
  const std::int64_t start = toUtime(now());
  odometry.sendTransform(edge("odom", "base", start));
  ahead.sendTransform(edge("odom", "base", start + 3'600'000'000, -999.0));
  odometry.sendTransform(edge("odom", "base", start + 10'000));
  drain(lcm);
  EXPECT_EQ(listener.statistics().stamped_ahead, 0u);
  EXPECT_EQ(buffer.statistics().rejectedTotal(), 1u);
  EXPECT_EQ(buffer.lookupTransform("odom", "base", kLatestTime).transform.translation.x(), -999.0);
  EXPECT_FALSE(buffer.canTransform("odom", "base", fromUtime(start)));
}

// The rest of a batch with one transform far ahead is stored, and the sender's newest stamp is
// not moved by the refused one: its next batch is not taken for a jump back.
TEST(TransformListener, ABatchWithOneTransformFarAheadKeepsTheRestAndItsSendersNewest) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.reporter = nullptr;
  TransformListener listener(buffer, lcm, options);
  const std::int64_t start = toUtime(now());
  receive(listener, "driver", 1,
          {edge("odom", "base", start), edge("odom", "arm", start + 1'000'000'000'000)},
          kTfChannel);
  for (int i = 1; i <= 3; ++i) {
    receive(listener, "driver", 1 + i, {edge("odom", "base", start + i * 10'000)}, kTfChannel);
  }
  EXPECT_EQ(listener.statistics().stamped_ahead, 1u);
  EXPECT_EQ(listener.statistics().stale_batches, 0u);
  EXPECT_EQ(listener.statistics().transforms, 4u);
  EXPECT_FALSE(buffer.frameExists("arm"));
  EXPECT_EQ(toUtime(buffer.lookupTransform("odom", "base", kLatestTime).stamp), start + 30'000);
}

// Stamps a little ahead, as from a computer whose clock is slightly ahead, are kept; static
// transforms are kept whatever their stamp (a static edge holds one value, not a history).
TEST(TransformListener, StampsWithinTheLimitAndStaticTransformsAreKept) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener listener(buffer, lcm);
  TransformBroadcaster driver(lcm, kTfChannel, "driver");
  StaticTransformBroadcaster statics(lcm);
  const std::int64_t ahead = toUtime(now()) + 5'000'000;
  driver.sendTransform(edge("odom", "base", ahead));
  statics.sendTransform(edge("base", "camera", ahead + 3'600'000'000));
  drain(lcm);
  EXPECT_EQ(listener.statistics().stamped_ahead, 0u);
  EXPECT_EQ(toUtime(buffer.lookupTransform("odom", "camera", kLatestTime).stamp), ahead);
}

TEST(TransformListener, ANegativeLimitOnStampsAheadIsRefused) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.max_stamp_ahead = -std::chrono::seconds(1);
  try {
    TransformListener listener(buffer, lcm, options);
    ADD_FAILURE() << "a negative max_stamp_ahead was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("max_stamp_ahead must not be negative"));
  }
}

// Its requests for statics would go out with a name that every broadcaster refuses to decode.
TEST(TransformListener, ANameItCouldNotSendItsRequestsWithIsRefused) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.authority = std::string(257, 'a');
  try {
    TransformListener listener(buffer, lcm, options);
    ADD_FAILURE() << "an authority too long to send was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("TransformListener: authority 'aaa"));
    EXPECT_THAT(e.what(), HasSubstr("is 257 bytes long"));
  }
}

// LCM's udpm self test fails on port 0, which its test datagram never comes back from, after
// waiting 10 s for it; LCM's C++ side still returns a subscription.
TEST(TransformListener, AnLcmThatCannotReceiveMakesTheListenerThrowNamingTheChannel) {
  lcm::LCM lcm("udpm://239.255.76.67:0?ttl=0");
  ASSERT_TRUE(lcm.good());
  Buffer buffer;
  ListenerOptions options;
  options.request_statics_at_start = false;
  try {
    TransformListener listener(buffer, lcm, options);
    ADD_FAILURE() << "a listener was made on an LCM that cannot subscribe";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("LCM cannot subscribe to TF_STATIC: it cannot receive"));
  }
}

TEST(TransformListener, OwnThreadModeListensOnItsOwnLcm) {
  Buffer buffer;
  ListenerOptions options;
  options.lcm_url = lcmtf_test::privateUdpmUrl("TransformListener.OwnThreadMode");
  TransformListener listener(buffer, options);
  TransformBroadcaster broadcaster(options.lcm_url);
  ASSERT_TRUE(broadcaster.sendTransform(edge("map", "odom", 1'000'000)));
  std::string why;
  EXPECT_TRUE(buffer.canTransform("map", "odom", kLatestTime, std::chrono::seconds(5), &why))
      << why;
}

}  // namespace
}  // namespace lcmtf
