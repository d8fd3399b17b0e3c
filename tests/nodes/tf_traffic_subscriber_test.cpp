#include "lcmtf/nodes/tf_traffic_subscriber.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/resend_request_t.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/wire_decode.hpp"

#include "support/wire_samples.hpp"

namespace lcmtf::nodes {
namespace {

using testing::HasSubstr;

constexpr TimePoint kStamp = lcmtf_test::kToolsEpoch;

struct RequestCounter {
  void onRequest(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
    resend_request_t request;
    if (decodeMessage(buffer->data, buffer->data_size, request))
      requesters.push_back(request.requester);
  }
  std::vector<std::string> requesters;
};

void handleAll(lcm::LCM& lcm) {
  while (lcm.handleTimeout(0) > 0) {
  }
}

TEST(TfTrafficSubscriber, RecordsBothChannelsWithTheirReceiveTimes) {
  lcm::LCM lcm("memq://");
  TfConnection connection;
  TfTraffic traffic;
  int observed = 0;
  TfTrafficSubscriber subscriber(lcm, connection, traffic,
                                 [&](const tf_message_t&, bool, TimePoint) { ++observed; });
  const TimePoint before = now();
  TransformBroadcaster dynamic(lcm, "TF", "robot");
  TransformBroadcaster statics(lcm, "TF_STATIC", "mounts");
  dynamic.sendTransform({kStamp, "odom", "base", Transform()});
  statics.sendTransform({kStamp, "base", "camera", Transform()});
  handleAll(lcm);
  const TrafficSummary summary = traffic.summarize(before, now(), std::chrono::seconds(10));
  ASSERT_EQ(summary.edges.size(), 2u);
  EXPECT_EQ(summary.edges[0].child, "base");
  EXPECT_FALSE(summary.edges[0].is_static);
  EXPECT_EQ(summary.edges[1].child, "camera");
  EXPECT_TRUE(summary.edges[1].is_static);
  EXPECT_EQ(observed, 2);
}

TEST(TfTrafficSubscriber, CountsMalformedMessagesOnEitherChannel) {
  lcm::LCM lcm("memq://");
  TfConnection connection;
  TfTraffic traffic;
  TfTrafficSubscriber subscriber(lcm, connection, traffic);
  const std::uint8_t garbage[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  lcm.publish("TF", garbage, sizeof garbage);
  lcm.publish("TF_STATIC", garbage, 3);
  handleAll(lcm);
  const TrafficSummary summary = traffic.summarize(kStamp, now(), std::chrono::seconds(10));
  EXPECT_EQ(summary.malformed, 2u);
  EXPECT_TRUE(summary.edges.empty());
  ASSERT_EQ(summary.problems.size(), 1u);
  EXPECT_THAT(summary.problems[0], HasSubstr("malformed messages (first, on TF: "));
}

TEST(TfTrafficSubscriber, ListensOnTheChannelsItIsGiven) {
  lcm::LCM lcm("memq://");
  TfConnection connection;
  connection.tf_channel = "ROBOT_TF";
  connection.request_channel = "ASK";
  TfTraffic traffic;
  TfTrafficSubscriber subscriber(lcm, connection, traffic);
  RequestCounter requests;
  lcm.subscribe("ASK", &RequestCounter::onRequest, &requests);
  TransformBroadcaster(lcm, "TF", "robot").sendTransform({kStamp, "odom", "base", Transform()});
  TransformBroadcaster(lcm, "ROBOT_TF", "robot")
      .sendTransform({kStamp, "odom", "arm", Transform()});
  subscriber.requestStatics("viewer");
  handleAll(lcm);
  const TrafficSummary summary = traffic.summarize(kStamp, now(), std::chrono::seconds(10));
  ASSERT_EQ(summary.edges.size(), 1u);
  EXPECT_EQ(summary.edges[0].child, "arm");
  EXPECT_THAT(requests.requesters, testing::ElementsAre("viewer"));
}

}  // namespace
}  // namespace lcmtf::nodes
