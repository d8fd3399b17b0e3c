// The listener's reporter is the user's code: it may ask the listener for its statistics, wait
// for a thread that does (as Python's reporter waits for the interpreter's lock), or throw.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <stdexcept>
#include <vector>

#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/transform_listener.hpp"

namespace lcmtf {
namespace {

using std::chrono::seconds;
using testing::HasSubstr;

TransformStamped edge(const std::string& parent, const std::string& child, std::int64_t utime) {
  return TransformStamped{fromUtime(utime), parent, child, Transform{}};
}

void drain(lcm::LCM& lcm) {
  while (lcm.handleTimeout(0) > 0) {
  }
}

// Refusals of three kinds, each reported once: a sender not allowed, a malformed message, and a
// transform stamped an hour ahead.
void sendRefusals(lcm::LCM& lcm) {
  TransformBroadcaster intruder(lcm, kTfChannel, "intruder");
  TransformBroadcaster trusted(lcm, kTfChannel, "trusted");
  intruder.sendTransform(edge("map", "odom", toUtime(now())));
  const std::uint8_t junk[] = {1, 2, 3};
  lcm.publish(kTfChannel, junk, sizeof junk);
  trusted.sendTransform(edge("map", "odom", toUtime(now()) + 3'600'000'000));
  trusted.sendTransform(edge("map", "odom", toUtime(now())));
  drain(lcm);
}

TEST(ListenerReporter, MayAskItsListenerForTheStatistics) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener* self = nullptr;
  std::vector<std::uint64_t> refusals_seen;
  ListenerOptions options;
  options.allowed_authorities = {"trusted"};
  options.reporter = [&](const std::string&) {
    const ListenerStatistics statistics = self->statistics();
    refusals_seen.push_back(statistics.unauthorized + statistics.malformed +
                            statistics.stamped_ahead);
  };
  TransformListener listener(buffer, lcm, options);
  self = &listener;
  sendRefusals(lcm);
  EXPECT_THAT(refusals_seen, testing::ElementsAre(1u, 2u, 3u));
  EXPECT_TRUE(buffer.canTransform("map", "odom", kLatestTime));
}

// Another thread asking for the statistics while the reporter waits for it is answered.
TEST(ListenerReporter, MayWaitForAThreadThatAsksForTheStatistics) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  TransformListener* self = nullptr;
  std::vector<std::future<ListenerStatistics>> askers;  // outlive the reporter's calls
  int answered_in_time = 0;
  ListenerOptions options;
  options.allowed_authorities = {"trusted"};
  options.reporter = [&](const std::string&) {
    askers.push_back(std::async(std::launch::async, [self] { return self->statistics(); }));
    if (askers.back().wait_for(seconds(5)) == std::future_status::ready) ++answered_in_time;
  };
  TransformListener listener(buffer, lcm, options);
  self = &listener;
  sendRefusals(lcm);
  EXPECT_EQ(askers.size(), 3u);
  EXPECT_EQ(answered_in_time, 3);
}

TEST(ListenerReporter, OneThatThrowsIsWrittenToStderrAndTheListenerGoesOn) {
  lcm::LCM lcm("memq://");
  Buffer buffer;
  ListenerOptions options;
  options.allowed_authorities = {"trusted"};
  options.reporter = [](const std::string&) { throw std::runtime_error("cannot log"); };
  TransformListener listener(buffer, lcm, options);
  testing::internal::CaptureStderr();
  sendRefusals(lcm);
  const std::string written = testing::internal::GetCapturedStderr();
  EXPECT_THAT(written, HasSubstr("its reporter threw (cannot log) on: ignored transforms from "
                                 "'intruder'"));
  EXPECT_THAT(written, HasSubstr("ignored a malformed message"));
  EXPECT_EQ(listener.statistics().stamped_ahead, 1u);
  EXPECT_EQ(listener.statistics().transforms, 1u);
  EXPECT_TRUE(buffer.canTransform("map", "odom", kLatestTime));
}

}  // namespace
}  // namespace lcmtf
