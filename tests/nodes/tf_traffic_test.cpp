#include "lcmtf/nodes/tf_traffic.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/wire_samples.hpp"

namespace lcmtf::nodes {
namespace {

using lcmtf_test::wireBatch;
using lcmtf_test::wireTransform;
using std::chrono::milliseconds;
using testing::ElementsAre;
using testing::HasSubstr;

constexpr TimePoint kStart = lcmtf_test::kToolsEpoch;
constexpr Duration kCache = std::chrono::seconds(10);

// `count` batches of parent -> child from `authority`, one every `period`, each received
// `delay` after its stamp.
void stream(TfTraffic& traffic, const std::string& authority, const std::string& parent,
            const std::string& child, int count, milliseconds period, milliseconds delay,
            TimePoint first = kStart) {
  for (int i = 0; i < count; ++i) {
    const TimePoint stamp = first + i * period;
    traffic.record(wireBatch(authority, {wireTransform(parent, child, stamp)}), false,
                   stamp + delay);
  }
}

const EdgeTraffic& find(const TrafficSummary& summary, const std::string& parent,
                        const std::string& child) {
  for (const EdgeTraffic& edge : summary.edges) {
    if (edge.parent == parent && edge.child == child) return edge;
  }
  throw std::runtime_error("no edge " + parent + " -> " + child);
}

TEST(TfTraffic, RateIsSamplesOverTheirReceiveSpanAndDelayIsReceiveMinusStamp) {
  TfTraffic traffic;
  stream(traffic, "robot", "odom", "base", 101, milliseconds(20), milliseconds(3));
  const TrafficSummary summary =
      traffic.summarize(kStart, kStart + std::chrono::seconds(5), kCache);
  ASSERT_EQ(summary.edges.size(), 1u);
  const EdgeTraffic& base = summary.edges[0];
  EXPECT_EQ(base.samples, 101u);
  EXPECT_DOUBLE_EQ(base.rate_hz, 50.0);
  EXPECT_NEAR(base.average_delay_s, 0.003, 1e-12);
  EXPECT_NEAR(base.max_delay_s, 0.003, 1e-12);
  EXPECT_THAT(base.authorities, ElementsAre("robot"));
  EXPECT_EQ(base.newest_stamp, kStart + milliseconds(2000));
  EXPECT_EQ(base.oldest_stamp, kStart);
  EXPECT_EQ(base.buffered, 101u);
  EXPECT_FALSE(base.is_static);
  EXPECT_EQ(summary.messages, 101u);
}

TEST(TfTraffic, AverageAndMaxDelayFollowEachSample) {
  TfTraffic traffic;
  for (int i = 0; i < 4; ++i) {
    const TimePoint stamp = kStart + i * milliseconds(100);
    traffic.record(wireBatch("robot", {wireTransform("odom", "base", stamp)}), false,
                   stamp + milliseconds(i * 10));
  }
  const EdgeTraffic base =
      traffic.summarize(kStart, kStart + std::chrono::seconds(1), kCache).edges[0];
  EXPECT_NEAR(base.average_delay_s, 0.015, 1e-12);
  EXPECT_NEAR(base.max_delay_s, 0.030, 1e-12);
}

TEST(TfTraffic, AuthorityRateCountsBatchesNotTransforms) {
  TfTraffic traffic;
  for (int i = 0; i < 11; ++i) {
    const TimePoint stamp = kStart + i * milliseconds(100);
    traffic.record(wireBatch("urdf", {wireTransform("base", "wheel_left", stamp),
                                      wireTransform("base", "wheel_right", stamp)}),
                   false, stamp + milliseconds(1));
  }
  const TrafficSummary summary =
      traffic.summarize(kStart, kStart + std::chrono::seconds(2), kCache);
  ASSERT_EQ(summary.authorities.size(), 1u);
  const AuthorityTraffic& urdf = summary.authorities[0];
  EXPECT_EQ(urdf.messages, 11u);
  EXPECT_DOUBLE_EQ(urdf.rate_hz, 10.0);
  EXPECT_EQ(urdf.dynamic_samples, 22u);
  EXPECT_NEAR(urdf.average_delay_s, 0.001, 1e-12);
  EXPECT_THAT(urdf.frames, ElementsAre("wheel_left", "wheel_right"));
}

TEST(TfTraffic, StaticEdgesAreMarkedAndHaveNoDelay) {
  TfTraffic traffic;
  for (int i = 0; i < 3; ++i) {
    traffic.record(wireBatch("mounts", {wireTransform("base", "camera", kStart)}), true,
                   kStart + std::chrono::seconds(100 + i));
  }
  const TrafficSummary summary =
      traffic.summarize(kStart, kStart + std::chrono::seconds(200), kCache);
  const EdgeTraffic& camera = find(summary, "base", "camera");
  EXPECT_TRUE(camera.is_static);
  EXPECT_EQ(camera.average_delay_s, 0.0);
  EXPECT_EQ(camera.max_delay_s, 0.0);
  EXPECT_EQ(camera.buffered, 1u);
  EXPECT_DOUBLE_EQ(camera.rate_hz, 1.0);
  EXPECT_EQ(summary.authorities[0].dynamic_samples, 0u);
}

TEST(TfTraffic, TwoAuthoritiesSendingOneFrameAreAConflict) {
  TfTraffic traffic;
  stream(traffic, "beta", "map", "base", 5, milliseconds(50), milliseconds(1));  // heard first
  stream(traffic, "alpha", "odom", "base", 30, milliseconds(10), milliseconds(1));
  stream(traffic, "alpha", "base", "arm", 5, milliseconds(50), milliseconds(1));
  const TrafficSummary summary =
      traffic.summarize(kStart, kStart + std::chrono::seconds(1), kCache);
  ASSERT_EQ(summary.conflicts.size(), 1u);
  EXPECT_EQ(summary.conflicts[0].child, "base");
  EXPECT_THAT(summary.conflicts[0].senders,
              ElementsAre("'alpha' (parent 'odom', dynamic, 30 transforms)",
                          "'beta' (parent 'map', dynamic, 5 transforms)"));
  EXPECT_EQ(find(summary, "odom", "base").samples, 30u);
  EXPECT_EQ(find(summary, "map", "base").samples, 5u);
}

TEST(TfTraffic, OneAuthorityReparentingAFrameIsNoConflict) {
  TfTraffic traffic;
  stream(traffic, "gripper", "table", "cup", 5, milliseconds(10), milliseconds(1));
  stream(traffic, "gripper", "hand", "cup", 5, milliseconds(10), milliseconds(1),
         kStart + milliseconds(50));
  const TrafficSummary summary =
      traffic.summarize(kStart, kStart + std::chrono::seconds(1), kCache);
  EXPECT_TRUE(summary.conflicts.empty());
  EXPECT_EQ(summary.edges.size(), 2u);
}

TEST(TfTraffic, LeadingSlashNamesTheSameEdge) {
  TfTraffic traffic;
  traffic.record(wireBatch("a", {wireTransform("/odom", "/base", kStart)}), false, kStart);
  traffic.record(wireBatch("a", {wireTransform("odom", "base", kStart + milliseconds(10))}), false,
                 kStart + milliseconds(10));
  const TrafficSummary summary =
      traffic.summarize(kStart, kStart + std::chrono::seconds(1), kCache);
  ASSERT_EQ(summary.edges.size(), 1u);
  EXPECT_EQ(summary.edges[0].samples, 2u);
}

TEST(TfTraffic, InvalidTransformsAreCountedAndDescribedButNotRecorded) {
  TfTraffic traffic;
  transform_t not_finite = wireTransform("odom", "base", kStart);
  not_finite.translation.x = std::numeric_limits<double>::quiet_NaN();
  transform_t zero_rotation = wireTransform("odom", "base", kStart);
  zero_rotation.rotation.w = 0.0;
  traffic.record(
      wireBatch("bad", {wireTransform("", "base", kStart), wireTransform("base", "base", kStart),
                        not_finite, zero_rotation, wireTransform("odom", "good", kStart)}),
      false, kStart);
  const TrafficSummary summary =
      traffic.summarize(kStart, kStart + std::chrono::seconds(1), kCache);
  EXPECT_EQ(summary.invalid_transforms, 4u);
  ASSERT_EQ(summary.edges.size(), 1u);
  EXPECT_EQ(summary.edges[0].child, "good");
  ASSERT_EQ(summary.problems.size(), 1u);
  EXPECT_THAT(summary.problems[0], HasSubstr("invalid transforms (first, from 'bad': empty parent "
                                             "frame name in '' -> 'base' at "));
}

TEST(TfTraffic, MalformedMessagesAreCountedWithTheFirstReason) {
  TfTraffic traffic;
  traffic.recordMalformed("TF", "truncated");
  traffic.recordMalformed("TF_STATIC", "bad fingerprint");
  const TrafficSummary summary = traffic.summarize(kStart, kStart, kCache);
  EXPECT_EQ(summary.malformed, 2u);
  EXPECT_THAT(summary.problems, ElementsAre("malformed messages (first, on TF: truncated)"));
}

TEST(TfTraffic, EdgesAndAuthoritiesBeyondTheLimitsAreRefusedAndCounted) {
  TrafficLimits limits;
  limits.max_edges = 3;
  limits.max_authorities = 2;
  TfTraffic traffic(limits);
  for (int i = 0; i < 5; ++i) {
    traffic.record(wireBatch("a", {wireTransform("root", "frame" + std::to_string(i), kStart)}),
                   false, kStart);
  }
  traffic.record(wireBatch("b", {wireTransform("root", "frame0", kStart)}), false, kStart);
  traffic.record(wireBatch("c", {wireTransform("root", "frame0", kStart)}), false, kStart);
  const TrafficSummary summary = traffic.summarize(kStart, kStart, kCache);
  EXPECT_EQ(summary.edges.size(), 3u);
  EXPECT_EQ(summary.refused, 3u);
  EXPECT_THAT(summary.problems,
              ElementsAre(HasSubstr("beyond 2 authorities (first: 'c')"),
                          HasSubstr("beyond 3 edges (first: 'root' -> 'frame3')")));
}

TEST(TfTraffic, ArrivalsPerEdgeAreBoundedKeepingTheNewest) {
  TrafficLimits limits;
  limits.max_arrivals_per_edge = 10;
  TfTraffic traffic(limits);
  stream(traffic, "robot", "odom", "base", 50, milliseconds(10), milliseconds(0));
  const EdgeTraffic base =
      traffic.summarize(kStart, kStart + std::chrono::seconds(1), kCache).edges[0];
  EXPECT_EQ(base.samples, 10u);
  EXPECT_DOUBLE_EQ(base.rate_hz, 100.0);
  EXPECT_EQ(base.newest_stamp, kStart + milliseconds(490));
}

TEST(TfTraffic, ArrivalsOverAllEdgesAreBoundedUntilForgotten) {
  TrafficLimits limits;
  limits.max_arrivals = 30;
  TfTraffic traffic(limits);
  stream(traffic, "robot", "odom", "base", 20, milliseconds(10), milliseconds(0));
  stream(traffic, "robot", "base", "arm", 20, milliseconds(10), milliseconds(0));
  TrafficSummary summary = traffic.summarize(kStart, kStart + std::chrono::seconds(1), kCache);
  EXPECT_EQ(find(summary, "odom", "base").samples, 20u);
  EXPECT_EQ(find(summary, "base", "arm").samples, 10u);
  EXPECT_EQ(summary.refused, 10u);
  EXPECT_THAT(summary.problems,
              ElementsAre("transforms refused beyond 30 held at once (first: 'base' -> 'arm')"));
  traffic.forgetBefore(kStart + milliseconds(100));
  stream(traffic, "robot", "base", "arm", 10, milliseconds(10), milliseconds(0),
         kStart + milliseconds(200));
  summary = traffic.summarize(kStart, kStart + std::chrono::seconds(1), kCache);
  EXPECT_EQ(find(summary, "base", "arm").samples, 10u);
  EXPECT_EQ(summary.refused, 10u);
}

TEST(TfTraffic, SummaryCountsOnlyArrivalsInTheWindowAndForgetSlidesIt) {
  TfTraffic traffic;
  stream(traffic, "robot", "odom", "base", 200, milliseconds(10), milliseconds(0));
  const TrafficSummary second_half =
      traffic.summarize(kStart + milliseconds(1000), kStart + milliseconds(1990), kCache);
  EXPECT_EQ(second_half.edges[0].samples, 100u);
  EXPECT_EQ(second_half.edges[0].buffered, 200u);
  traffic.forgetBefore(kStart + milliseconds(1500));
  const TrafficSummary after = traffic.summarize(kStart, kStart + milliseconds(1990), kCache);
  EXPECT_EQ(after.edges[0].samples, 50u);
  EXPECT_EQ(after.authorities[0].messages, 50u);
}

TEST(TfTraffic, BufferedCountsDistinctStampsWithinTheCacheTimeOfTheNewest) {
  TfTraffic traffic;
  stream(traffic, "robot", "odom", "base", 21, std::chrono::milliseconds(1000), milliseconds(0));
  traffic.record(
      wireBatch("robot", {wireTransform("odom", "base", kStart + std::chrono::seconds(20))}), false,
      kStart + std::chrono::seconds(21));
  const EdgeTraffic base =
      traffic.summarize(kStart, kStart + std::chrono::seconds(30), kCache).edges[0];
  EXPECT_EQ(base.buffered, 11u);  // stamps 10 s ... 20 s, the repeated one counted once
  EXPECT_EQ(base.oldest_stamp, kStart + std::chrono::seconds(10));
}

TEST(TfTraffic, ExtremeStampsFromTheNetworkDoNotOverflow) {
  TfTraffic traffic;
  for (std::int64_t stamp : {std::numeric_limits<std::int64_t>::min(),
                             std::numeric_limits<std::int64_t>::max(), std::int64_t{0}}) {
    traffic.record(wireBatch("odd", {wireTransform("odom", "base", fromUtime(stamp))}), false,
                   kStart);
  }
  const EdgeTraffic base = traffic.summarize(kStart, kStart, kCache).edges[0];
  EXPECT_EQ(base.samples, 3u);
  EXPECT_TRUE(std::isfinite(base.average_delay_s));
  EXPECT_EQ(base.buffered, 1u);
}

}  // namespace
}  // namespace lcmtf::nodes
