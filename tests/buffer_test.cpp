#include "lcmtf/buffer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <thread>

namespace lcmtf {
namespace {

using namespace std::chrono_literals;
using testing::HasSubstr;

TransformStamped edge(const std::string& parent, const std::string& child, std::int64_t utime,
                      double x = 1.0) {
  return TransformStamped{fromUtime(utime), parent, child,
                          Transform(Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity())};
}

// Inserts `transform` into `buffer` after `delay`, from another thread.
class LateInsert {
 public:
  LateInsert(Buffer& buffer, TransformStamped transform, std::chrono::milliseconds delay)
      : thread_([&buffer, transform, delay] {
          std::this_thread::sleep_for(delay);
          buffer.setTransform(transform, "late");
        }) {}
  ~LateInsert() { thread_.join(); }

 private:
  std::thread thread_;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(Buffer, LookupWithTimeoutAnswersAtOnceWhenDataIsThere) {
  Buffer buffer;
  buffer.setTransform(edge("map", "base", 1'000'000), "test");
  const auto start = std::chrono::steady_clock::now();
  const TransformStamped t = buffer.lookupTransform("map", "base", fromUtime(1'000'000), 5s);
  EXPECT_LT(secondsSince(start), 1.0);
  EXPECT_EQ(t.transform.translation.x(), 1.0);
}

TEST(Buffer, LookupWithTimeoutWakesWhenTheDataArrives) {
  Buffer buffer;
  buffer.setTransform(edge("map", "base", 1'000'000), "test");
  const auto start = std::chrono::steady_clock::now();
  LateInsert late(buffer, edge("map", "base", 2'000'000, 3.0), 50ms);
  const TransformStamped t = buffer.lookupTransform("map", "base", fromUtime(1'500'000), 30s);
  EXPECT_LT(secondsSince(start), 15.0) << "woke by the timeout, not by the insert";
  EXPECT_DOUBLE_EQ(t.transform.translation.x(), 2.0);
}

TEST(Buffer, LookupWaitsForAFrameThatDoesNotExistYet) {
  Buffer buffer;
  LateInsert late(buffer, edge("map", "camera", 5'000'000), 30ms);
  const TransformStamped t = buffer.lookupTransform("map", "camera", kLatestTime, 30s);
  EXPECT_EQ(toUtime(t.stamp), 5'000'000);
}

TEST(Buffer, TimeoutExceptionSaysWhatWasAwaitedAndWhatIsMissing) {
  Buffer buffer;
  buffer.setTransform(edge("map", "base", 1'000'000), "test");
  try {
    buffer.lookupTransform("map", "base", fromUtime(3'000'000), 50ms);
    FAIL() << "expected TimeoutException";
  } catch (const TimeoutException& e) {
    EXPECT_THAT(e.what(), HasSubstr("timed out after 0.050000 s waiting for a transform of "
                                    "'base' into 'map' at 3.000000"));
    EXPECT_THAT(e.what(), HasSubstr("extrapolation into the future"));
  }
}

TEST(Buffer, TimeoutNamesTheUnknownFrame) {
  Buffer buffer;
  try {
    buffer.lookupTransform("map", "nowhere", kLatestTime, 20ms);
    FAIL() << "expected TimeoutException";
  } catch (const TimeoutException& e) {
    EXPECT_THAT(e.what(), HasSubstr("'nowhere'"));
    EXPECT_THAT(e.what(), HasSubstr("does not exist"));
  }
}

TEST(Buffer, TimeFallenOutOfTheWindowFailsWithoutWaitingForTheTimeout) {
  Buffer buffer(1s);
  buffer.setTransform(edge("map", "base", 10'000'000), "test");
  LateInsert late(buffer, edge("map", "base", 20'000'000), 30ms);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(buffer.lookupTransform("map", "base", fromUtime(5'000'000), 30s),
               PastExtrapolationException);
  EXPECT_LT(secondsSince(start), 15.0);
}

TEST(Buffer, CanTransformWithTimeoutWaitsThenSaysWhy) {
  Buffer buffer;
  std::string why;
  EXPECT_FALSE(buffer.canTransform("map", "base", kLatestTime, 20ms, &why));
  EXPECT_THAT(why, HasSubstr("does not exist"));
  LateInsert late(buffer, edge("map", "base", 1'000'000), 30ms);
  EXPECT_TRUE(buffer.canTransform("map", "base", kLatestTime, 30s, &why));
}

TEST(Buffer, TimeTravelLookupWaitsForBothHalves) {
  Buffer buffer;
  buffer.setTransform(edge("odom", "base", 1'000'000, 1.0), "test");
  buffer.setTransform(TransformStamped{TimePoint{}, "base", "camera", Transform::identity()},
                      "test", true);
  LateInsert late(buffer, edge("odom", "base", 2'000'000, 5.0), 30ms);
  const TransformStamped t = buffer.lookupTransform("base", fromUtime(2'000'000), "camera",
                                                    fromUtime(1'000'000), "odom", 30s);
  EXPECT_DOUBLE_EQ(t.transform.translation.x(), -4.0);
  EXPECT_EQ(toUtime(t.stamp), 2'000'000);

  std::string why;
  EXPECT_FALSE(buffer.canTransform("base", fromUtime(9'000'000), "camera", fromUtime(1'000'000),
                                   "odom", 20ms, &why));
  EXPECT_THAT(why, HasSubstr("future"));
  EXPECT_THROW(buffer.lookupTransform("base", fromUtime(9'000'000), "camera", fromUtime(1'000'000),
                                      "odom", 20ms),
               TimeoutException);
}

TEST(Buffer, WaitForTransformFutureIsFulfilledByTheInsert) {
  Buffer buffer;
  std::future<TransformStamped> future =
      buffer.waitForTransform("map", "base", fromUtime(1'000'000), 30s);
  EXPECT_EQ(future.wait_for(0ms), std::future_status::timeout);
  buffer.setTransform(edge("map", "base", 1'000'000, 7.0), "test");
  ASSERT_EQ(future.wait_for(10s), std::future_status::ready);
  EXPECT_EQ(future.get().transform.translation.x(), 7.0);
}

TEST(Buffer, WaitForTransformIsReadyAtOnceWhenAvailable) {
  Buffer buffer;
  buffer.setTransform(edge("map", "base", 1'000'000, 2.0), "test");
  std::future<TransformStamped> future = buffer.waitForTransform("map", "base", kLatestTime, 1s);
  ASSERT_EQ(future.wait_for(0ms), std::future_status::ready);
  EXPECT_EQ(future.get().transform.translation.x(), 2.0);
}

TEST(Buffer, WaitForTransformTimesOutWithTimeoutException) {
  Buffer buffer;
  std::future<TransformStamped> future = buffer.waitForTransform("map", "base", kLatestTime, 30ms);
  ASSERT_EQ(future.wait_for(10s), std::future_status::ready);
  EXPECT_THROW(future.get(), TimeoutException);
}

TEST(Buffer, DroppedFuturesAndDestroyedBufferEndCleanly) {
  std::future<TransformStamped> kept;
  {
    Buffer buffer;
    buffer.waitForTransform("map", "base", kLatestTime, 10s);
    kept = buffer.waitForTransform("map", "camera", kLatestTime, 10s);
  }
  ASSERT_EQ(kept.wait_for(0ms), std::future_status::ready);
  try {
    kept.get();
    FAIL() << "expected TimeoutException";
  } catch (const TimeoutException& e) {
    EXPECT_THAT(e.what(), HasSubstr("buffer destroyed"));
  }
}

}  // namespace
}  // namespace lcmtf
