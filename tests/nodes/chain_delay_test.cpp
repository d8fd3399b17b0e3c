#include "lcmtf/nodes/chain_delay.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lcmtf/message_conversions.hpp"

#include "support/wire_samples.hpp"

namespace lcmtf::nodes {
namespace {

using std::chrono::milliseconds;
using testing::ElementsAre;
using testing::HasSubstr;

constexpr TimePoint kStart = lcmtf_test::kToolsEpoch;

// Stores parent_T_child at `stamp` in `buffer`, and hands the same batch to `meter` as
// received at `received`.
void arrive(BufferCore& buffer, ChainDelayMeter& meter, const std::string& parent,
            const std::string& child, TimePoint stamp, TimePoint received) {
  const TransformStamped transform{stamp, parent, child, Transform()};
  ASSERT_TRUE(buffer.setTransform(transform, "test"));
  tf_message_t batch{};
  batch.transforms.push_back(toMessage(transform));
  batch.num_transforms = 1;
  meter.onBatch(batch, false, received);
}

TEST(ChainDelay, NetDelayIsReceiveTimeMinusTheChainsLatestCommonTime) {
  BufferCore buffer;
  buffer.setTransform({kStart, "base", "camera", Transform()}, "mounts", true);
  ChainDelayMeter meter(buffer, "map", "camera");
  arrive(buffer, meter, "map", "odom", kStart, kStart + milliseconds(1));
  arrive(buffer, meter, "odom", "base", kStart, kStart + milliseconds(2));
  // odom advances; the chain's newest common time stays at base's stamp until base follows.
  arrive(buffer, meter, "map", "odom", kStart + milliseconds(100), kStart + milliseconds(101));
  arrive(buffer, meter, "odom", "base", kStart + milliseconds(100), kStart + milliseconds(104));
  const ChainReport report = meter.report();
  EXPECT_THAT(report.frames, ElementsAre("map", "odom", "base", "camera"));
  EXPECT_TRUE(report.problem.empty());
  ASSERT_EQ(report.samples, 3u);  // the first arrival left the chain unconnected
  EXPECT_NEAR(report.average_delay_s, (0.002 + 0.101 + 0.004) / 3, 1e-9);
  EXPECT_NEAR(report.max_delay_s, 0.101, 1e-9);
}

TEST(ChainDelay, ArrivalsOffTheChainAreNotMeasured) {
  BufferCore buffer;
  ChainDelayMeter meter(buffer, "odom", "base");
  arrive(buffer, meter, "odom", "base", kStart, kStart + milliseconds(5));
  arrive(buffer, meter, "base", "wheel", kStart, kStart + milliseconds(500));
  EXPECT_EQ(meter.report().samples, 1u);
  meter.reset();
  EXPECT_EQ(meter.report().samples, 0u);
  EXPECT_EQ(meter.report().max_delay_s, 0.0);
}

TEST(ChainDelay, AStaticChainHasNoDelay) {
  BufferCore buffer;
  buffer.setTransform({kStart, "base", "camera", Transform()}, "mounts", true);
  ChainDelayMeter meter(buffer, "base", "camera");
  tf_message_t batch{};
  meter.onBatch(batch, true, kStart);
  const ChainReport report = meter.report();
  EXPECT_THAT(report.frames, ElementsAre("base", "camera"));
  EXPECT_EQ(report.samples, 0u);
}

TEST(ChainDelay, MissingChainSaysWhy) {
  BufferCore buffer;
  buffer.setTransform({kStart, "map", "odom", Transform()}, "a");
  buffer.setTransform({kStart, "base", "camera", Transform()}, "b");
  EXPECT_THAT(ChainDelayMeter(buffer, "map", "camera").report().problem,
              HasSubstr("not connected"));
  EXPECT_THAT(ChainDelayMeter(buffer, "map", "nowhere").report().problem,
              HasSubstr("'nowhere' does not exist"));
}

}  // namespace
}  // namespace lcmtf::nodes
