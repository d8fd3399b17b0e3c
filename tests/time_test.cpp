#include "lcmtf/time.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace lcmtf {
namespace {

TEST(Time, UtimeRoundTripsExactly) {
  for (std::int64_t utime :
       {std::int64_t{0}, std::int64_t{1}, std::int64_t{-1}, std::int64_t{1'700'000'000'123'456},
        std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min()}) {
    EXPECT_EQ(toUtime(fromUtime(utime)), utime);
  }
}

TEST(Time, ZeroTimePointMeansLatest) {
  EXPECT_EQ(kLatestTime, TimePoint{});
  EXPECT_EQ(toUtime(kLatestTime), 0);
}

TEST(Time, TimePointCountsMicrosecondsSinceUnixEpoch) {
  const TimePoint t = fromUtime(1'500'000);
  EXPECT_EQ(std::chrono::duration_cast<std::chrono::milliseconds>(t.time_since_epoch()).count(),
            1500);
  EXPECT_EQ(std::chrono::system_clock::to_time_t(t), 1);
}

TEST(Time, SecondsConversionRoundsToNearestMicrosecond) {
  EXPECT_EQ(secondsToDuration(0.0000014), Duration(1));
  EXPECT_EQ(secondsToDuration(0.0000016), Duration(2));
  EXPECT_EQ(secondsToDuration(-2.5), Duration(-2'500'000));
  EXPECT_EQ(toUtime(fromSeconds(1700000000.25)), 1'700'000'000'250'000);
  EXPECT_DOUBLE_EQ(toSeconds(fromUtime(2'500'000)), 2.5);
  EXPECT_DOUBLE_EQ(toSeconds(Duration(-750)), -0.00075);
}

TEST(Time, NowIsCloseToSystemClock) {
  const auto before = std::chrono::system_clock::now();
  const TimePoint t = now();
  const auto after = std::chrono::system_clock::now();
  EXPECT_LE(before - std::chrono::microseconds(1), t);
  EXPECT_LE(t, after);
}

TEST(Time, ToStringPrintsSecondsWithMicrosecondDigits) {
  EXPECT_EQ(toString(fromUtime(1'700'000'000'000'250)), "1700000000.000250");
  EXPECT_EQ(toString(kLatestTime), "0.000000");
  EXPECT_EQ(toString(fromUtime(-1'500'000)), "-1.500000");
  EXPECT_EQ(toString(Duration(250'000)), "0.250000 s");
  EXPECT_EQ(toString(Duration(-3)), "-0.000003 s");
  EXPECT_EQ(toString(fromUtime(std::numeric_limits<std::int64_t>::min())), "-9223372036854.775808");
}

}  // namespace
}  // namespace lcmtf
