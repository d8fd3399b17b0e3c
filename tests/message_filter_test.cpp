#include "lcmtf/message_filter.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <condition_variable>
#include <stdexcept>
#include <thread>

namespace lcmtf {
namespace {

using namespace std::chrono_literals;
using testing::HasSubstr;

struct Detection {
  std::string frame;
  TimePoint stamp;
  int label = 0;
};

TransformStamped edge(const std::string& parent, const std::string& child, std::int64_t utime) {
  return TransformStamped{fromUtime(utime), parent, child,
                          Transform(Eigen::Vector3d(1, 0, 0), Eigen::Quaterniond::Identity())};
}

// Records what a filter passes and drops, and lets a test wait for it.
class Recorder {
 public:
  void ready(const Detection& d) {
    std::lock_guard<std::mutex> guard(mutex_);
    passed_.push_back(d.label);
    changed_.notify_all();
  }
  void dropped(const Detection& d, FilterDropReason reason, const std::string& why) {
    std::lock_guard<std::mutex> guard(mutex_);
    dropped_.push_back({d.label, reason, why});
    changed_.notify_all();
  }
  bool waitForEvents(std::size_t count) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, 10s, [&] { return passed_.size() + dropped_.size() >= count; });
  }
  std::vector<int> passed() {
    std::lock_guard<std::mutex> guard(mutex_);
    return passed_;
  }
  struct Drop {
    int label;
    FilterDropReason reason;
    std::string why;
  };
  std::vector<Drop> dropped() {
    std::lock_guard<std::mutex> guard(mutex_);
    return dropped_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<int> passed_;
  std::vector<Drop> dropped_;
};

class MessageFilterTest : public ::testing::Test {
 protected:
  std::unique_ptr<MessageFilter<Detection>> makeFilter(MessageFilterOptions options) {
    return std::make_unique<MessageFilter<Detection>>(
        buffer, std::move(options), [](const Detection& d) { return d.frame; },
        [](const Detection& d) { return d.stamp; },
        [this](const Detection& d) { recorder.ready(d); },
        [this](const Detection& d, FilterDropReason reason, const std::string& why) {
          recorder.dropped(d, reason, why);
        });
  }
  static MessageFilterOptions targets(std::vector<std::string> frames) {
    MessageFilterOptions options;
    options.target_frames = std::move(frames);
    return options;
  }
  Buffer buffer{std::chrono::seconds(2)};
  Recorder recorder;
};

TEST_F(MessageFilterTest, TransformableMessagePassesAtOnce) {
  buffer.setTransform(edge("map", "camera", 1'000'000), "test");
  auto filter = makeFilter(targets({"map"}));
  filter->add({"camera", fromUtime(1'000'000), 7});
  EXPECT_EQ(recorder.passed(), std::vector<int>{7});
  EXPECT_EQ(filter->pending(), 0u);
  EXPECT_EQ(filter->statistics().passed, 1u);
}

TEST_F(MessageFilterTest, MessageWaitsUntilTheInsertThatMakesItTransformable) {
  buffer.setTransform(edge("map", "camera", 1'000'000), "test");
  auto filter = makeFilter(targets({"map"}));
  filter->add({"camera", fromUtime(1'500'000), 1});
  EXPECT_TRUE(recorder.passed().empty());
  EXPECT_EQ(filter->pending(), 1u);
  buffer.setTransform(edge("map", "camera", 2'000'000), "test");
  EXPECT_EQ(recorder.passed(), std::vector<int>{1});
  EXPECT_EQ(filter->pending(), 0u);
}

TEST_F(MessageFilterTest, EveryTargetFrameMustBeReachable) {
  buffer.setTransform(edge("map", "camera", 1'000'000), "test");
  auto filter = makeFilter(targets({"map", "base"}));
  filter->add({"camera", fromUtime(1'000'000), 3});
  EXPECT_TRUE(recorder.passed().empty());
  buffer.setTransform(edge("base", "map", 1'000'000), "test");
  EXPECT_EQ(recorder.passed(), std::vector<int>{3});
}

TEST_F(MessageFilterTest, FullQueueDropsTheOldestWithItsReason) {
  MessageFilterOptions options = targets({"map"});
  options.queue_size = 2;
  auto filter = makeFilter(options);
  for (int label = 1; label <= 3; ++label) filter->add({"camera", fromUtime(1'000'000), label});
  const auto dropped = recorder.dropped();
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_EQ(dropped[0].label, 1);
  EXPECT_EQ(dropped[0].reason, FilterDropReason::kQueueFull);
  EXPECT_THAT(dropped[0].why, HasSubstr("queue of 2"));
  EXPECT_EQ(filter->pending(), 2u);
  buffer.setTransform(edge("map", "camera", 1'000'000), "test");
  EXPECT_EQ(recorder.passed(), (std::vector<int>{2, 3}));
  EXPECT_EQ(filter->statistics().droppedCount(FilterDropReason::kQueueFull), 1u);
}

TEST_F(MessageFilterTest, TransformableMessagePassesWithoutEvictingFromAFullQueue) {
  buffer.setTransform(edge("map", "camera", 1'000'000), "test");
  MessageFilterOptions options = targets({"map"});
  options.queue_size = 2;
  auto filter = makeFilter(options);
  filter->add({"camera", fromUtime(1'500'000), 1});
  filter->add({"camera", fromUtime(1'500'000), 2});
  filter->add({"camera", fromUtime(1'000'000), 3});
  EXPECT_EQ(recorder.passed(), std::vector<int>{3});
  EXPECT_TRUE(recorder.dropped().empty());
  EXPECT_EQ(filter->pending(), 2u);
  buffer.setTransform(edge("map", "camera", 2'000'000), "test");
  EXPECT_EQ(recorder.passed(), (std::vector<int>{3, 1, 2}));
}

TEST_F(MessageFilterTest, ZeroQueueSizeIsRefused) {
  MessageFilterOptions options = targets({"map"});
  options.queue_size = 0;
  try {
    makeFilter(options);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("queue_size"));
  }
}

TEST_F(MessageFilterTest, MessageThatWaitsTooLongIsDroppedOnItsOwn) {
  MessageFilterOptions options = targets({"map"});
  options.timeout = 30ms;
  auto filter = makeFilter(options);
  filter->add({"camera", fromUtime(1'000'000), 5});
  ASSERT_TRUE(recorder.waitForEvents(1));
  const auto dropped = recorder.dropped();
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_EQ(dropped[0].reason, FilterDropReason::kTimeout);
  EXPECT_THAT(dropped[0].why, HasSubstr("'camera'"));
  EXPECT_EQ(filter->pending(), 0u);
}

TEST_F(MessageFilterTest, MessageOlderThanTheCacheIsDroppedAsFailed) {
  buffer.setTransform(edge("map", "camera", 10'000'000), "test");
  auto filter = makeFilter(targets({"map"}));
  filter->add({"camera", fromUtime(9'000'000), 9});
  EXPECT_TRUE(recorder.dropped().empty());
  buffer.setTransform(edge("map", "camera", 12'000'000), "test");
  const auto dropped = recorder.dropped();
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_EQ(dropped[0].reason, FilterDropReason::kTransformFailed);
  EXPECT_THAT(dropped[0].why, HasSubstr("past"));
}

TEST_F(MessageFilterTest, InvalidFrameIsDroppedNotThrown) {
  auto filter = makeFilter(targets({"map"}));
  filter->add({"", fromUtime(1'000'000), 4});
  const auto dropped = recorder.dropped();
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_EQ(dropped[0].reason, FilterDropReason::kTransformFailed);
}

TEST_F(MessageFilterTest, DestroyedFilterCallsNothingMore) {
  auto filter = makeFilter(targets({"map"}));
  filter->add({"camera", fromUtime(1'000'000), 1});
  filter.reset();
  buffer.setTransform(edge("map", "camera", 1'000'000), "test");
  EXPECT_TRUE(recorder.passed().empty());
  EXPECT_TRUE(recorder.dropped().empty());
}

TEST_F(MessageFilterTest, MessagesArrivingFromAnotherThreadAllPass) {
  auto filter = makeFilter(targets({"map"}));
  std::thread producer([&] {
    for (int label = 0; label < 50; ++label) {
      filter->add({"camera", fromUtime(1'000'000 + label * 10'000), label});
    }
  });
  for (int i = 0; i <= 50; ++i)
    buffer.setTransform(edge("map", "camera", 1'000'000 + i * 10'000), "test");
  producer.join();
  ASSERT_TRUE(recorder.waitForEvents(50));
  EXPECT_EQ(recorder.passed().size(), 50u);
}

}  // namespace
}  // namespace lcmtf
