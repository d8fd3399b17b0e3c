// How many messages LCM holds for a listener while they wait to be handled. LCM's memq://
// provider holds every message whatever the capacity, so these use udpm (ttl=0).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/transform_listener.hpp"
#include "support/test_lcm.hpp"

namespace lcmtf {
namespace {

using std::chrono::milliseconds;
using testing::HasSubstr;

// Messages of this size fit in one datagram, so that none is lost in pieces.
constexpr std::size_t kLargeMessage = 30'000;

lcm::LCM privateLcm() {
  return lcm::LCM(
      lcmtf_test::privateUdpmUrl(testing::UnitTest::GetInstance()->current_test_info()->name()));
}

// Gives LCM's receiving thread time to queue what was sent, then handles all of it.
void settleAndDrain(lcm::LCM& lcm) {
  std::this_thread::sleep_for(milliseconds(500));
  while (lcm.handleTimeout(0) > 0) {
  }
}

void publishBytes(lcm::LCM& lcm, const std::string& channel, std::size_t size, int times) {
  const std::vector<char> bytes(size, 'x');
  for (int i = 0; i < times; ++i) {
    lcm.publish(channel, bytes.data(), static_cast<unsigned int>(bytes.size()));
    std::this_thread::sleep_for(milliseconds(1));
  }
}

void sendBatches(TransformBroadcaster& broadcaster, int count) {
  for (int i = 1; i <= count; ++i) {
    broadcaster.sendTransform(
        TransformStamped{fromUtime(1'000 * i), "map", "odom", Transform::identity()});
    std::this_thread::sleep_for(milliseconds(1));
  }
}

ListenerOptions optionsWithBudget(std::size_t queue_bytes) {
  ListenerOptions options;
  options.queue_bytes = queue_bytes;
  options.request_statics_at_start = false;
  return options;
}

TEST(ListenerQueue, LargeMessagesMakeLcmHoldOnlyWhatFitsInTheBudget) {
  lcm::LCM lcm = privateLcm();
  ASSERT_TRUE(lcm.good());
  Buffer buffer;
  ListenerOptions options = optionsWithBudget(100'000);
  std::vector<std::string> reports;
  options.reporter = [&reports](const std::string& message) { reports.push_back(message); };
  TransformListener listener(buffer, lcm, options);

  publishBytes(lcm, kTfChannel, kLargeMessage, 1);
  settleAndDrain(lcm);
  ASSERT_EQ(listener.statistics().queue_shortened, 1u);
  ASSERT_FALSE(reports.empty());
  EXPECT_THAT(reports.front(), HasSubstr("30000 bytes on TF"));
  EXPECT_THAT(reports.front(), HasSubstr("queue 2 messages"));

  // Ten more while nothing handles them: LCM keeps three (one more than it was told).
  publishBytes(lcm, kTfChannel, kLargeMessage, 10);
  settleAndDrain(lcm);
  EXPECT_EQ(listener.statistics().malformed, 1u + 3u);
  EXPECT_EQ(listener.statistics().queue_shortened, 1u);
}

TEST(ListenerQueue, BatchesOfTheUsualSizeKeepTheWholeCount) {
  lcm::LCM lcm = privateLcm();
  ASSERT_TRUE(lcm.good());
  Buffer buffer;
  TransformListener listener(buffer, lcm, optionsWithBudget(ListenerOptions{}.queue_bytes));
  TransformBroadcaster broadcaster(lcm);
  sendBatches(broadcaster, 50);
  settleAndDrain(lcm);
  EXPECT_EQ(listener.statistics().messages, 50u);
  EXPECT_EQ(listener.statistics().queue_shortened, 0u);
}

TEST(ListenerQueue, LargeMessagesOnOneChannelLeaveTheOthersQueueAlone) {
  lcm::LCM lcm = privateLcm();
  ASSERT_TRUE(lcm.good());
  Buffer buffer;
  ListenerOptions options = optionsWithBudget(50'000);
  options.reporter = nullptr;
  TransformListener listener(buffer, lcm, options);
  publishBytes(lcm, kTfChannel, kLargeMessage, 1);
  settleAndDrain(lcm);

  TransformBroadcaster broadcaster(lcm);
  sendBatches(broadcaster, 5);
  publishBytes(lcm, kTfStaticChannel, 100, 5);
  settleAndDrain(lcm);
  const ListenerStatistics statistics = listener.statistics();
  EXPECT_EQ(statistics.messages, 2u);        // room for two on TF: the rest were dropped
  EXPECT_EQ(statistics.malformed, 1u + 5u);  // TF_STATIC kept all five
}

}  // namespace
}  // namespace lcmtf
