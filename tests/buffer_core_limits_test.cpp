// Limits a user sets on what the buffer keeps and interpolates: samples per edge, and the
// widest gap between two samples a lookup may interpolate across.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "lcmtf/buffer_core.hpp"
#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::put;
using ::testing::HasSubstr;

Transform along(double x) {
  return Transform(Eigen::Vector3d(x, 0.0, 0.0), Eigen::Quaterniond::Identity());
}

std::uint64_t refusedAsFull(const BufferCore& buffer) {
  return buffer.statistics().rejectedCount(InsertRejection::kEdgeFull);
}

TEST(BufferCoreSampleBound, DefaultCoversTheCacheTimeAtAboveOneKilohertz) {
  EXPECT_GE(BufferCore().mostSamplesPerEdge(), 10'000u);
  EXPECT_GE(BufferCore(std::chrono::seconds(60)).mostSamplesPerEdge(), 60'000u);
  EXPECT_GE(BufferCore(std::chrono::milliseconds(1)).mostSamplesPerEdge(), 64u);
}

TEST(BufferCoreSampleBound, AFullEdgeDropsItsOldestSampleForANewerOne) {
  BufferCore buffer;
  buffer.setMostSamplesPerEdge(4);
  for (int i = 0; i < 10; ++i) put(buffer, "map", "robot", at(i * 0.001), along(i));
  EXPECT_EQ(buffer.statistics().dropped_for_room, 6u);
  EXPECT_FALSE(buffer.canTransform("map", "robot", at(0.0055)));
  EXPECT_NEAR(buffer.lookupTransform("map", "robot", at(0.0065)).transform.translation.x(), 6.5,
              1e-9);
  EXPECT_NEAR(buffer.lookupTransform("map", "robot", kLatestTime).transform.translation.x(), 9.0,
              1e-12);
}

TEST(BufferCoreSampleBound, ALateSampleInsideAFullEdgeTakesTheOldestOnesPlace) {
  BufferCore buffer;
  buffer.setMostSamplesPerEdge(3);
  put(buffer, "map", "robot", at(1), along(1));
  put(buffer, "map", "robot", at(3), along(3));
  put(buffer, "map", "robot", at(4), along(4));
  put(buffer, "map", "robot", at(2), along(2));
  EXPECT_FALSE(buffer.canTransform("map", "robot", at(1.5)));
  EXPECT_NEAR(buffer.lookupTransform("map", "robot", at(2.5)).transform.translation.x(), 2.5, 1e-9);
}

TEST(BufferCoreSampleBound, ASampleOlderThanAllOfAFullEdgeIsRefusedCountedAndNamed) {
  BufferCore buffer;
  buffer.setErrorReporter(nullptr);
  buffer.setMostSamplesPerEdge(2);
  put(buffer, "map", "robot", at(2), along(2));
  put(buffer, "map", "robot", at(3), along(3));
  std::string error;
  EXPECT_FALSE(buffer.setTransform(TransformStamped{at(1), "map", "robot", along(1)}, "late", false,
                                   &error));
  EXPECT_THAT(error, HasSubstr("'map' -> 'robot'"));
  EXPECT_THAT(error, HasSubstr("most samples (2)"));
  EXPECT_EQ(refusedAsFull(buffer), 1u);
  EXPECT_FALSE(buffer.setTransform(TransformStamped{at(1), "elsewhere", "robot", along(1)}, "late",
                                   false, &error));
  EXPECT_FALSE(buffer.frameExists("elsewhere"));
  EXPECT_NEAR(buffer.lookupTransform("map", "robot", at(2.5)).transform.translation.x(), 2.5, 1e-9);
}

TEST(BufferCoreSampleBound, AFloodAtAnyRateKeepsAtMostTheBoundPerEdge) {
  BufferCore buffer;
  buffer.setMostSamplesPerEdge(100);
  for (int i = 0; i < 100'000; ++i) put(buffer, "map", "robot", at(i * 1e-6), along(i));
  EXPECT_EQ(buffer.statistics().dropped_for_room, 100'000u - 100u);
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("samples: 100\n"));
  EXPECT_FALSE(buffer.canTransform("map", "robot", at(99'899e-6)));
  EXPECT_TRUE(buffer.canTransform("map", "robot", at(99'900e-6)));
}

TEST(BufferCoreSampleBound, FewerThanTwoSamplesPerEdgeIsRefused) {
  BufferCore buffer;
  EXPECT_THROW(buffer.setMostSamplesPerEdge(1), std::invalid_argument);
}

class BufferCoreInterpolationGap : public ::testing::Test {
 protected:
  void SetUp() override {
    put(buffer_, "map", "odom", at(0), along(0));
    put(buffer_, "map", "odom", at(0.1), along(1));
    put(buffer_, "map", "odom", at(2.1), along(21));  // two seconds of lost messages
    put(buffer_, "map", "odom", at(2.2), along(22));
    put(buffer_, "odom", "base", at(0), along(0), true);
  }
  BufferCore buffer_;
};

TEST_F(BufferCoreInterpolationGap, IsOffByDefaultAndInterpolatesAcrossTheHole) {
  EXPECT_EQ(buffer_.maxInterpolationGap(), Duration::zero());
  EXPECT_NEAR(buffer_.lookupTransform("map", "base", at(1.1)).transform.translation.x(), 11.0,
              1e-9);
}

TEST_F(BufferCoreInterpolationGap, ALookupInsideAWiderGapFailsNamingTheEdgeAndTheGap) {
  buffer_.setMaxInterpolationGap(std::chrono::milliseconds(500));
  try {
    buffer_.lookupTransform("map", "base", at(1.1));
    FAIL() << "expected InterpolationGapException";
  } catch (const InterpolationGapException& e) {
    EXPECT_THAT(e.what(), HasSubstr("'map' -> 'odom'"));
    EXPECT_THAT(e.what(), HasSubstr("2.000000 s apart"));
    EXPECT_THAT(e.what(), HasSubstr("maximum interpolation gap of 0.500000 s"));
  }
  EXPECT_THROW(buffer_.lookupTransform("base", "map", at(1.1)), ExtrapolationException);
  std::string why;
  EXPECT_FALSE(buffer_.canTransform("map", "base", at(1.1), &why));
  EXPECT_THAT(why, HasSubstr("gap"));
  EXPECT_THROW(buffer_.lookupTransform("base", at(1.1), "base", at(2.15), "map"),
               InterpolationGapException);
}

TEST_F(BufferCoreInterpolationGap, LookupsBetweenCloseSamplesOrAtASampleStillAnswer) {
  buffer_.setMaxInterpolationGap(std::chrono::milliseconds(500));
  EXPECT_NEAR(buffer_.lookupTransform("map", "base", at(0.05)).transform.translation.x(), 0.5,
              1e-9);
  EXPECT_NEAR(buffer_.lookupTransform("map", "base", at(2.1)).transform.translation.x(), 21.0,
              1e-9);
  EXPECT_NEAR(buffer_.lookupTransform("map", "base", kLatestTime).transform.translation.x(), 22.0,
              1e-9);
  EXPECT_NEAR(
      buffer_.lookupTransform("base", at(2.15), "base", at(0.05), "map").transform.translation.x(),
      -21.0, 1e-9);
}

TEST_F(BufferCoreInterpolationGap, ALimitAsWideAsTheGapAllowsIt) {
  buffer_.setMaxInterpolationGap(std::chrono::seconds(2));
  EXPECT_TRUE(buffer_.canTransform("map", "base", at(1.1)));
  EXPECT_THROW(buffer_.setMaxInterpolationGap(std::chrono::seconds(-1)), std::invalid_argument);
}

}  // namespace
}  // namespace lcmtf
