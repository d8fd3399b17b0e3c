#include "lcmtf/sendable_names.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>

#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf/wire_decode.hpp"

namespace lcmtf {
namespace {

using testing::HasSubstr;

const std::size_t kLongest = DecodeLimits{}.max_name_bytes;

TransformStamped edge(const std::string& parent, const std::string& child, double x = 1.0) {
  return TransformStamped{fromUtime(1'000'000), parent, child,
                          Transform(Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity())};
}

void drain(lcm::LCM& lcm) {
  while (lcm.handleTimeout(0) > 0) {
  }
}

// A listener on its own memq LCM, and what reached its buffer.
struct Receiver {
  lcm::LCM lcm{"memq://"};
  Buffer buffer;
  TransformListener listener{buffer, lcm};
};

std::string textMessage(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

TEST(SendableNames, NamesUpToTheListenersLimitCanBeSent) {
  EXPECT_EQ(whyUnsendable("base_link"), "");
  EXPECT_EQ(whyUnsendable(""), "");  // refused one by one at listeners, not with the batch
  EXPECT_EQ(whyUnsendable(std::string(kLongest, 'a')), "");
}

TEST(SendableNames, LongerNamesAndNulBytesCannot) {
  EXPECT_THAT(whyUnsendable(std::string(kLongest + 1, 'a')),
              HasSubstr("is 257 bytes long: listeners refuse a batch with a name longer than "
                        "256 bytes"));
  EXPECT_THAT(whyUnsendable(std::string("cam\0era", 7)), HasSubstr("holds a NUL byte"));
}

TEST(SendableNames, TheProblemQuotesTheStartOfALongName) {
  const std::string problem =
      unsendableNameProblem("child frame name", "camera_" + std::string(400, 'x'));
  EXPECT_THAT(problem, HasSubstr("child frame name 'camera_xxx"));
  EXPECT_THAT(problem, HasSubstr("...' is 407 bytes long"));
  EXPECT_LT(problem.size(), 200u);
  EXPECT_EQ(unsendableNameProblem("child frame name", "camera"), "");
}

TEST(SendableNames, TheLongestNameABroadcasterSendsReachesTheListener) {
  Receiver receiver;
  TransformBroadcaster broadcaster(receiver.lcm);
  const std::string longest(kLongest, 'c');
  ASSERT_TRUE(broadcaster.sendTransform(edge("map", longest)));
  drain(receiver.lcm);
  EXPECT_TRUE(receiver.buffer.canTransform("map", longest, kLatestTime));
  EXPECT_EQ(receiver.listener.statistics().malformed, 0u);
}

TEST(SendableNames, ABroadcasterSendsNothingOfABatchWithALongerName) {
  Receiver receiver;
  TransformBroadcaster broadcaster(receiver.lcm);
  const std::string longer(kLongest + 1, 'c');
  const std::string why = textMessage([&] {
    broadcaster.sendTransform({edge("map", "odom"), edge("odom", longer)});
  });
  EXPECT_THAT(why, HasSubstr("child frame name 'ccc"));
  EXPECT_THAT(why, HasSubstr("257 bytes long"));
  drain(receiver.lcm);
  EXPECT_EQ(receiver.listener.statistics().messages, 0u);
  EXPECT_FALSE(receiver.buffer.canTransform("map", "odom", kLatestTime));

  ASSERT_TRUE(broadcaster.sendTransform(edge("map", "odom")));
  drain(receiver.lcm);
  EXPECT_TRUE(receiver.buffer.canTransform("map", "odom", kLatestTime));
}

TEST(SendableNames, ABroadcasterRefusesAParentNameWithANulByte) {
  lcm::LCM lcm("memq://");
  TransformBroadcaster broadcaster(lcm);
  EXPECT_THAT(textMessage([&] { broadcaster.sendTransform(edge(std::string("ma\0p", 4), "b")); }),
              HasSubstr("parent frame name 'ma\\x00p' holds a NUL byte"));
}

TEST(SendableNames, BroadcastersRefuseALongerSenderName) {
  lcm::LCM lcm("memq://");
  const std::string longer(kLongest + 1, 's');
  EXPECT_THAT(textMessage([&] { TransformBroadcaster(lcm, kTfChannel, longer); }),
              HasSubstr("sender name 'sss"));
  StaticBroadcasterOptions options;
  options.authority = longer;
  EXPECT_THAT(textMessage([&] { StaticTransformBroadcaster(lcm, options); }),
              HasSubstr("sender name 'sss"));
}

// Kept, the name would go out with the whole set on every resend, and every listener would
// refuse every batch holding it.
TEST(SendableNames, AStaticBroadcasterKeepsNoneOfASetWithALongerName) {
  Receiver receiver;
  StaticBroadcasterOptions options;
  options.resend_period = Duration::zero();
  StaticTransformBroadcaster statics(receiver.lcm, options);
  ASSERT_TRUE(statics.sendTransform(edge("base", "camera")));
  const std::string longer(kLongest + 1, 'l');
  EXPECT_THAT(textMessage([&] {
                statics.sendTransform({edge("base", "lidar"), edge("base", longer)});
              }),
              HasSubstr("257 bytes long"));
  EXPECT_EQ(statics.size(), 1u);
  drain(receiver.lcm);
  EXPECT_TRUE(receiver.buffer.canTransform("base", "camera", kLatestTime));
  EXPECT_FALSE(receiver.buffer.canTransform("base", "lidar", kLatestTime));
  EXPECT_EQ(receiver.listener.statistics().malformed, 0u);
}

}  // namespace
}  // namespace lcmtf
