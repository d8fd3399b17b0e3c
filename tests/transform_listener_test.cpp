#include "lcmtf/transform_listener.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "support/sample_messages.hpp"
#include "support/test_lcm.hpp"

namespace lcmtf {
namespace {

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
