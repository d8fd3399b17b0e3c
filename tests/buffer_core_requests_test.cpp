// BufferCore transformable requests: a callback when a lookup becomes possible or never will.
#include "lcmtf/buffer_core.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;

const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

struct Call {
  TransformableRequestHandle handle;
  std::string target;
  std::string source;
  TimePoint time;
  TransformableResult result;
};

class TransformableRequests : public ::testing::Test {
 protected:
  TransformableCallback record() {
    return [this](TransformableRequestHandle handle, const std::string& target,
                  const std::string& source, TimePoint time, TransformableResult result) {
      calls_.push_back(Call{handle, target, source, time, result});
    };
  }
  BufferCore buffer_;
  std::vector<Call> calls_;
};

TEST_F(TransformableRequests, AlreadyTransformableReturnsZeroAndNeverCalls) {
  put(buffer_, "world", "base", at(1), pose({1, 0, 0}, 0, kZ));
  put(buffer_, "world", "base", at(2), pose({2, 0, 0}, 0, kZ));
  EXPECT_EQ(buffer_.addTransformableRequest(record(), "world", "base", at(1.5)), 0u);
  EXPECT_EQ(buffer_.addTransformableRequest(record(), "base", "world", kLatestTime), 0u);
  EXPECT_EQ(buffer_.addTransformableRequest(record(), "base", "base", at(7)), 0u);
  put(buffer_, "world", "base", at(3), pose({3, 0, 0}, 0, kZ));
  EXPECT_TRUE(calls_.empty());
}

TEST_F(TransformableRequests, FiresFromTheInsertThatMakesItTransformable) {
  put(buffer_, "world", "base", at(1), pose({1, 0, 0}, 0, kZ));
  const TransformableRequestHandle handle =
      buffer_.addTransformableRequest(record(), "world", "base", at(2));
  ASSERT_NE(handle, 0u);
  put(buffer_, "world", "base", at(1.5), pose({1.5, 0, 0}, 0, kZ));
  put(buffer_, "world", "other", at(3), pose({0, 0, 0}, 0, kZ));
  EXPECT_TRUE(calls_.empty());
  put(buffer_, "world", "base", at(2.5), pose({2.5, 0, 0}, 0, kZ));
  ASSERT_EQ(calls_.size(), 1u);
  EXPECT_EQ(calls_[0].handle, handle);
  EXPECT_EQ(calls_[0].target, "world");
  EXPECT_EQ(calls_[0].source, "base");
  EXPECT_EQ(calls_[0].time, at(2));
  EXPECT_EQ(calls_[0].result, TransformableResult::kAvailable);
  put(buffer_, "world", "base", at(3), pose({3, 0, 0}, 0, kZ));
  EXPECT_EQ(calls_.size(), 1u);
}

TEST_F(TransformableRequests, FiresOnceFramesThatDidNotExistAreConnected) {
  const TransformableRequestHandle handle =
      buffer_.addTransformableRequest(record(), "world", "camera", at(1));
  ASSERT_NE(handle, 0u);
  put(buffer_, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  EXPECT_TRUE(calls_.empty());
  putStatic(buffer_, "base", "camera", pose({0, 0, 1}, 0, kZ));
  ASSERT_EQ(calls_.size(), 1u);
  EXPECT_EQ(calls_[0].handle, handle);
  EXPECT_EQ(calls_[0].result, TransformableResult::kAvailable);
}

TEST_F(TransformableRequests, LatestTimeRequestFiresOnceThePathHasData) {
  const TransformableRequestHandle handle =
      buffer_.addTransformableRequest(record(), "a", "/c", kLatestTime);
  ASSERT_NE(handle, 0u);
  put(buffer_, "a", "b", at(1), pose({0, 0, 0}, 0, kZ));
  EXPECT_TRUE(calls_.empty());
  put(buffer_, "b", "c", at(5), pose({0, 0, 0}, 0, kZ));
  EXPECT_TRUE(calls_.empty());  // connected, but the two edges share no time yet
  put(buffer_, "a", "b", at(6), pose({0, 0, 0}, 0, kZ));
  ASSERT_EQ(calls_.size(), 1u);
  EXPECT_EQ(calls_[0].result, TransformableResult::kAvailable);
  EXPECT_EQ(calls_[0].time, kLatestTime);
}

TEST_F(TransformableRequests, FiresFailureOnceTheTimeFallsOutOfTheCacheWindow) {
  BufferCore buffer(std::chrono::seconds(1));
  std::vector<Call> calls;
  const auto callback = [&](TransformableRequestHandle handle, const std::string& target,
                            const std::string& source, TimePoint time, TransformableResult result) {
    calls.push_back(Call{handle, target, source, time, result});
  };
  putStatic(buffer, "world", "odom", pose({0, 0, 0}, 0, kZ));
  put(buffer, "odom", "base", at(1.5), pose({0, 0, 0}, 0, kZ));
  const TransformableRequestHandle handle =
      buffer.addTransformableRequest(callback, "world", "base", at(1));
  ASSERT_NE(handle, 0u);
  put(buffer, "odom", "base", at(2), pose({0, 0, 0}, 0, kZ));  // 1 s later: still in the window
  EXPECT_TRUE(calls.empty());
  put(buffer, "odom", "base", at(2) + Duration(1), pose({0, 0, 0}, 0, kZ));
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0].handle, handle);
  EXPECT_EQ(calls[0].time, at(1));
  EXPECT_EQ(calls[0].result, TransformableResult::kFailure);
  put(buffer, "odom", "base", at(3), pose({0, 0, 0}, 0, kZ));
  EXPECT_EQ(calls.size(), 1u);
}

TEST_F(TransformableRequests, RequestAlreadyOutOfTheWindowFailsFromTheNextInsert) {
  // Callbacks only ever run from setTransform, so a request that can never succeed is decided
  // by whatever is inserted next.
  BufferCore buffer(std::chrono::seconds(1));
  std::vector<TransformableResult> results;
  put(buffer, "world", "base", at(5), pose({0, 0, 0}, 0, kZ));
  ASSERT_NE(
      buffer.addTransformableRequest([&](auto, const std::string&, const std::string&, TimePoint,
                                         TransformableResult result) { results.push_back(result); },
                                     "world", "base", at(3)),
      0u);
  EXPECT_TRUE(results.empty());
  put(buffer, "map", "dock", at(9), pose({0, 0, 0}, 0, kZ));
  EXPECT_THAT(results, ::testing::ElementsAre(TransformableResult::kFailure));
}

TEST_F(TransformableRequests, LateSampleInsideTheWindowSatisfiesAPendingRequest) {
  BufferCore buffer(std::chrono::seconds(1));
  std::vector<TransformableResult> results;
  put(buffer, "world", "base", at(1.5), pose({0, 0, 0}, 0, kZ));
  put(buffer, "world", "base", at(2), pose({0, 0, 0}, 0, kZ));
  ASSERT_NE(
      buffer.addTransformableRequest([&](auto, const std::string&, const std::string&, TimePoint,
                                         TransformableResult result) { results.push_back(result); },
                                     "world", "base", at(1)),
      0u);
  put(buffer, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  EXPECT_THAT(results, ::testing::ElementsAre(TransformableResult::kAvailable));
}

TEST_F(TransformableRequests, CancelledRequestNeverFires) {
  const TransformableRequestHandle handle =
      buffer_.addTransformableRequest(record(), "world", "base", at(1));
  ASSERT_NE(handle, 0u);
  buffer_.cancelTransformableRequest(handle);
  buffer_.cancelTransformableRequest(handle);  // twice is harmless
  buffer_.cancelTransformableRequest(0);
  buffer_.cancelTransformableRequest(handle + 100);
  put(buffer_, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  EXPECT_TRUE(calls_.empty());
}

TEST_F(TransformableRequests, CancellingOneRequestLeavesTheOthers) {
  const TransformableRequestHandle first =
      buffer_.addTransformableRequest(record(), "world", "base", at(1));
  const TransformableRequestHandle second =
      buffer_.addTransformableRequest(record(), "base", "world", at(1));
  ASSERT_NE(first, 0u);
  ASSERT_NE(second, 0u);
  EXPECT_NE(first, second);
  buffer_.cancelTransformableRequest(first);
  put(buffer_, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  ASSERT_EQ(calls_.size(), 1u);
  EXPECT_EQ(calls_[0].handle, second);
}

TEST_F(TransformableRequests, OneInsertFiresEveryRequestItDecidesAndOnlyThose) {
  put(buffer_, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  std::set<TransformableRequestHandle> handles;
  for (const double t : {1.2, 1.5, 1.9}) {
    handles.insert(buffer_.addTransformableRequest(record(), "world", "base", at(t)));
  }
  const TransformableRequestHandle later =
      buffer_.addTransformableRequest(record(), "world", "base", at(3));
  EXPECT_EQ(handles.size(), 3u);
  EXPECT_EQ(handles.count(0), 0u);
  put(buffer_, "world", "base", at(2), pose({0, 0, 0}, 0, kZ));
  ASSERT_EQ(calls_.size(), 3u);
  std::set<TransformableRequestHandle> fired;
  for (const Call& call : calls_) {
    fired.insert(call.handle);
    EXPECT_EQ(call.result, TransformableResult::kAvailable);
  }
  EXPECT_EQ(fired, handles);
  put(buffer_, "world", "base", at(3), pose({0, 0, 0}, 0, kZ));
  ASSERT_EQ(calls_.size(), 4u);
  EXPECT_EQ(calls_[3].handle, later);
}

TEST_F(TransformableRequests, RequestsSurviveClear) {
  put(buffer_, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  ASSERT_NE(buffer_.addTransformableRequest(record(), "world", "base", at(2)), 0u);
  buffer_.clear();
  put(buffer_, "world", "base", at(2), pose({0, 0, 0}, 0, kZ));
  ASSERT_EQ(calls_.size(), 1u);
  EXPECT_EQ(calls_[0].result, TransformableResult::kAvailable);
}

TEST_F(TransformableRequests, RejectedInsertDecidesNothing) {
  ASSERT_NE(buffer_.addTransformableRequest(record(), "world", "base", at(1)), 0u);
  buffer_.setErrorReporter(nullptr);
  EXPECT_FALSE(buffer_.setTransform(
      lcmtf_test::stamped("world", "base", at(1), Transform({std::nan(""), 0, 0}, {1, 0, 0, 0})),
      "test"));
  EXPECT_TRUE(calls_.empty());
}

TEST_F(TransformableRequests, CallbackMayLookUpInTheBuffer) {
  put(buffer_, "world", "base", at(1), pose({1, 0, 0}, 0, kZ));
  Eigen::Vector3d seen = Eigen::Vector3d::Zero();
  ASSERT_NE(buffer_.addTransformableRequest(
                [&](TransformableRequestHandle, const std::string& target,
                    const std::string& source, TimePoint time, TransformableResult) {
                  seen = buffer_.lookupTransform(target, source, time).transform.translation;
                  EXPECT_TRUE(buffer_.canTransform(target, source, time));
                  EXPECT_EQ(buffer_.getLatestCommonTime(target, source), at(3));
                },
                "world", "base", at(2)),
            0u);
  put(buffer_, "world", "base", at(3), pose({3, 0, 0}, 0, kZ));
  EXPECT_LE((seen - Eigen::Vector3d(2, 0, 0)).norm(), 1e-12);
}

TEST_F(TransformableRequests, CallbackMayInsertAndThatInsertMayFireFurtherRequests) {
  // The first request's callback stores the edge that the second request waits for.
  put(buffer_, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  const TransformableRequestHandle second =
      buffer_.addTransformableRequest(record(), "world", "tool", at(2));
  const TransformableRequestHandle first = buffer_.addTransformableRequest(
      [&](TransformableRequestHandle, const std::string&, const std::string&, TimePoint time,
          TransformableResult result) {
        ASSERT_EQ(result, TransformableResult::kAvailable);
        put(buffer_, "base", "tool", time, pose({0, 0, 0.5}, 0, kZ));
      },
      "world", "base", at(2));
  ASSERT_NE(first, 0u);
  ASSERT_NE(second, 0u);
  put(buffer_, "world", "base", at(2), pose({0, 0, 0}, 0, kZ));
  ASSERT_EQ(calls_.size(), 1u);
  EXPECT_EQ(calls_[0].handle, second);
  EXPECT_EQ(calls_[0].result, TransformableResult::kAvailable);
  EXPECT_TRUE(buffer_.canTransform("world", "tool", at(2)));
}

TEST_F(TransformableRequests, CallbackMayAddAndCancelRequests) {
  TransformableRequestHandle added = 0;
  const TransformableRequestHandle doomed =
      buffer_.addTransformableRequest(record(), "world", "never", at(1));
  ASSERT_NE(doomed, 0u);
  ASSERT_NE(buffer_.addTransformableRequest(
                [&](auto, const std::string&, const std::string&, TimePoint, TransformableResult) {
                  buffer_.cancelTransformableRequest(doomed);
                  added = buffer_.addTransformableRequest(record(), "world", "base", at(5));
                },
                "world", "base", at(1)),
            0u);
  put(buffer_, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  ASSERT_NE(added, 0u);
  EXPECT_TRUE(calls_.empty());
  put(buffer_, "never", "x", at(1), pose({0, 0, 0}, 0, kZ));
  put(buffer_, "world", "never", at(1), pose({0, 0, 0}, 0, kZ));
  EXPECT_TRUE(calls_.empty());  // the cancelled one stays silent
  put(buffer_, "world", "base", at(5), pose({0, 0, 0}, 0, kZ));
  ASSERT_EQ(calls_.size(), 1u);
  EXPECT_EQ(calls_[0].handle, added);
}

}  // namespace
}  // namespace lcmtf
