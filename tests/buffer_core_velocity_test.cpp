// BufferCore::lookupVelocity: central differences over known motions, in closed form.
#include "lcmtf/buffer_core.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::isometry;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;
using ::testing::HasSubstr;

constexpr double kTolerance = 1e-11;
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

::testing::AssertionResult near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  const double error = (actual - expected).norm();
  if (error <= kTolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actual.transpose() << " vs expected "
                                       << expected.transpose() << " (error " << error << ")";
}

// odom -> base moves on a ramp: position p0 + v t, turning about a fixed axis at w rad/s;
// samples every 0.1 s from t = 0 to t = 5.
class RampMotion : public ::testing::Test {
 protected:
  const Eigen::Vector3d p0{1, -2, 0.5};
  const Eigen::Vector3d v{0.4, -0.3, 0.1};
  const double theta0 = 0.2;
  const double w = 0.5;
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 2).normalized();

  Eigen::Isometry3d odom_T_base(double t) const {
    return isometry(p0 + v * t, theta0 + w * t, axis);
  }

  void SetUp() override {
    for (int i = 0; i <= 50; ++i) {
      const double t = 0.1 * i;
      put(buffer_, "odom", "base", at(t), pose(p0 + v * t, theta0 + w * t, axis));
    }
  }
  BufferCore buffer_;
};

TEST_F(RampMotion, LinearAndAngularVelocityEqualTheRampRates) {
  for (const double t : {0.5, 2.5, 2.537, 4.25}) {
    const Velocity velocity =
        buffer_.lookupVelocity("base", "odom", at(t), std::chrono::milliseconds(200));
    EXPECT_TRUE(near(velocity.linear, v)) << "t " << t;
    EXPECT_TRUE(near(velocity.angular, w * axis)) << "t " << t;
    EXPECT_EQ(velocity.frame, "odom");
    EXPECT_EQ(velocity.stamp, at(t));
  }
}

TEST_F(RampMotion, AveragingIntervalNeedNotAlignWithSamples) {
  for (const Duration interval : {Duration(333'333), Duration(1'000), Duration(1'000'000)}) {
    const Velocity velocity = buffer_.lookupVelocity("base", "/odom", at(2.4321), interval);
    EXPECT_TRUE(near(velocity.linear, v)) << interval.count();
    EXPECT_TRUE(near(velocity.angular, w * axis)) << interval.count();
    EXPECT_EQ(velocity.frame, "odom");
  }
}

TEST_F(RampMotion, ObservationFrameOffsetByAStaticTransformSeesTheRatesRotatedIntoIt) {
  // obs is fixed in odom, turned 1.1 rad about (1, -2, 0.5) and shifted.
  const Eigen::Isometry3d odom_T_obs = isometry({3, 1, -1}, 1.1, {1, -2, 0.5});
  putStatic(buffer_, "odom", "obs", pose({3, 1, -1}, 1.1, {1, -2, 0.5}));
  const Eigen::Matrix3d obs_R_odom = odom_T_obs.linear().transpose();
  for (const double t : {1.0, 3.3}) {
    const Velocity velocity =
        buffer_.lookupVelocity("base", "obs", at(t), std::chrono::milliseconds(100));
    EXPECT_TRUE(near(velocity.linear, obs_R_odom * v)) << "t " << t;
    EXPECT_TRUE(near(velocity.angular, obs_R_odom * (w * axis))) << "t " << t;
    EXPECT_EQ(velocity.frame, "obs");
  }
}

TEST_F(RampMotion, VelocityOfTheParentSeenFromTheMovingFrameIsTheDifferenceOfTheInverse) {
  // odom relative to base, expressed in base: the chord of base_T_odom's translation, and the
  // turn reversed.
  const double t = 2.0;
  const double half = 0.15;
  const Eigen::Vector3d before = odom_T_base(t - half).inverse().translation();
  const Eigen::Vector3d after = odom_T_base(t + half).inverse().translation();
  const Velocity velocity =
      buffer_.lookupVelocity("odom", "base", at(t), std::chrono::milliseconds(300));
  EXPECT_TRUE(near(velocity.linear, (after - before) / (2 * half)));
  EXPECT_TRUE(near(velocity.angular, -w * axis));
  EXPECT_EQ(velocity.frame, "base");
}

TEST_F(RampMotion, IntervalIsClippedToTheAvailableDataAndTheStampKept) {
  const Velocity at_end = buffer_.lookupVelocity("base", "odom", at(5), std::chrono::seconds(1));
  EXPECT_TRUE(near(at_end.linear, v));
  EXPECT_TRUE(near(at_end.angular, w * axis));
  EXPECT_EQ(at_end.stamp, at(5));
  const Velocity at_start = buffer_.lookupVelocity("base", "odom", at(0), std::chrono::seconds(1));
  EXPECT_TRUE(near(at_start.linear, v));
  EXPECT_EQ(at_start.stamp, at(0));
  const Velocity latest =
      buffer_.lookupVelocity("base", "odom", kLatestTime, std::chrono::milliseconds(100));
  EXPECT_TRUE(near(latest.linear, v));
  EXPECT_EQ(latest.stamp, at(5));
}

TEST_F(RampMotion, VelocityWhereThereIsNoDataRaisesExtrapolationException) {
  try {
    buffer_.lookupVelocity("base", "odom", at(6), std::chrono::milliseconds(200));
    FAIL() << "did not throw";
  } catch (const ExtrapolationException& error) {
    const std::string message = error.what();
    EXPECT_THAT(message, HasSubstr("velocity of 'base' relative to 'odom' at " + toString(at(6))));
    EXPECT_THAT(message, HasSubstr("have data from " + toString(at(0)) + " to " + toString(at(5))));
  }
  EXPECT_THROW(buffer_.lookupVelocity("base", "odom", at(-1), std::chrono::milliseconds(200)),
               ExtrapolationException);
}

TEST(BufferCoreVelocity, PointOnATurntableMovesAtTheCentralDifferenceOfItsCircle) {
  // A sensor 0.8 m from the axis of a turntable turning at 0.7 rad/s: over an interval H the
  // central difference is r w sinc(w H / 2) along the tangent.
  constexpr double r = 0.8;
  constexpr double w = 0.7;
  BufferCore buffer;
  for (int i = 0; i <= 100; ++i)
    put(buffer, "odom", "table", at(0.1 * i), pose({0, 0, 0}, w * 0.1 * i, kZ));
  putStatic(buffer, "table", "sensor", pose({r, 0, 0.3}, 0.4, {1, 0, 0}));
  for (const double t : {2.0, 4.75}) {
    for (const double interval : {0.01, 0.2, 1.0}) {
      const Velocity velocity =
          buffer.lookupVelocity("sensor", "odom", at(t), secondsToDuration(interval));
      const double sinc = std::sin(w * interval / 2) / (w * interval / 2);
      const Eigen::Vector3d expected =
          r * w * sinc * Eigen::Vector3d(-std::sin(w * t), std::cos(w * t), 0);
      EXPECT_TRUE(near(velocity.linear, expected)) << "t " << t << " interval " << interval;
      EXPECT_TRUE(near(velocity.angular, w * kZ)) << "t " << t << " interval " << interval;
    }
  }
  // At the newest sample only the half interval before it is available.
  const double t = 10;
  const double half = 0.25;
  const Eigen::Vector3d before(r * std::cos(w * (t - half)), r * std::sin(w * (t - half)), 0.3);
  const Eigen::Vector3d now(r * std::cos(w * t), r * std::sin(w * t), 0.3);
  const Velocity clipped =
      buffer.lookupVelocity("sensor", "odom", at(t), std::chrono::milliseconds(500));
  EXPECT_TRUE(near(clipped.linear, (now - before) / half));
}

TEST(BufferCoreVelocity, FramesWithOnlyStaticEdgesBetweenThemHaveZeroVelocity) {
  BufferCore buffer;
  putStatic(buffer, "world", "base", pose({1, 2, 3}, 0.5, kZ));
  put(buffer, "world", "elsewhere", at(1), pose({0, 0, 0}, 0, kZ));
  for (const auto& [tracking, observation] : {std::pair<std::string, std::string>{"base", "world"},
                                              {"world", "base"},
                                              {"base", "base"}}) {
    const Velocity velocity =
        buffer.lookupVelocity(tracking, observation, at(7), std::chrono::milliseconds(100));
    EXPECT_EQ(velocity.linear, Eigen::Vector3d::Zero());
    EXPECT_EQ(velocity.angular, Eigen::Vector3d::Zero());
    EXPECT_EQ(velocity.frame, observation);
  }
}

TEST(BufferCoreVelocity, VelocityBetweenDisconnectedFramesRaisesConnectivityException) {
  BufferCore buffer;
  put(buffer, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  put(buffer, "map", "dock", at(1), pose({0, 0, 0}, 0, kZ));
  EXPECT_THROW(buffer.lookupVelocity("base", "dock", at(1), std::chrono::milliseconds(100)),
               ConnectivityException);
}

}  // namespace
}  // namespace lcmtf
