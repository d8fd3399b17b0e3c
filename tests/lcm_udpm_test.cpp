#include <gtest/gtest.h>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/wire_decode.hpp"
#include "support/child_process.hpp"
#include "support/sample_messages.hpp"
#include "support/test_lcm.hpp"

namespace lcmtf {
namespace {

using namespace std::chrono_literals;

class ReplyInbox {
 public:
  void onReply(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
    tf_message_t reply;
    if (decodeMessage(buffer->data, buffer->data_size, reply).ok) replies.push_back(reply);
  }
  std::vector<tf_message_t> replies;
};

// Publishes `request` until the peer answers (it may not have subscribed yet) or time runs out.
bool exchange(lcm::LCM& lcm, const tf_message_t& request, ReplyInbox& inbox,
              std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (inbox.replies.empty() && std::chrono::steady_clock::now() < deadline) {
    lcm.publish("REQUEST", &request);
    lcm.handleTimeout(50);
  }
  return !inbox.replies.empty();
}

std::string testUrl() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return lcmtf_test::privateUdpmUrl(std::string(info->test_suite_name()) + "." + info->name());
}

TEST(LcmUdpm, TwoProcessesRoundTripTransformsOverTtlZero) {
  const std::string url = testUrl();
  ASSERT_NE(url.find("ttl=0"), std::string::npos);
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good()) << "cannot open " << url;
  ReplyInbox inbox;
  lcm.subscribe("REPLY", &ReplyInbox::onReply, &inbox);

  lcmtf_test::ChildProcess peer(UDPM_ECHO_PEER, {url, "REQUEST", "REPLY", "1", "15000"});
  tf_message_t request = lcmtf_test::sampleTfMessage(3);
  for (transform_t& t : request.transforms) {
    t.rotation = toMessage(fromMessage(t.rotation).normalized());
  }
  ASSERT_TRUE(exchange(lcm, request, inbox, 10s)) << "no reply from the peer process on " << url;
  EXPECT_EQ(peer.waitForExit(5s), std::optional<int>(0));

  const tf_message_t& reply = inbox.replies.front();
  EXPECT_EQ(reply.authority, "udpm_echo_peer");
  ASSERT_EQ(reply.num_transforms, 3);
  for (std::size_t i = 0; i < 3; ++i) {
    const TransformStamped sent = fromMessage(request.transforms[i]);
    const TransformStamped back = fromMessage(reply.transforms[i]);
    EXPECT_EQ(back.parent_frame, sent.child_frame);
    EXPECT_EQ(back.child_frame, sent.parent_frame);
    EXPECT_EQ(back.stamp, sent.stamp);
    const Eigen::Vector3d point(0.3, -0.7, 2.0);
    EXPECT_LE((back.transform * (sent.transform * point) - point).norm(), 1e-9);
  }
}

TEST(LcmUdpm, PeerIgnoresGarbageAndStillAnswers) {
  const std::string url = testUrl();
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  ReplyInbox inbox;
  lcm.subscribe("REPLY", &ReplyInbox::onReply, &inbox);

  lcmtf_test::ChildProcess peer(UDPM_ECHO_PEER, {url, "REQUEST", "REPLY", "1", "15000"});
  const std::vector<std::uint8_t> garbage(100, 0xAB);
  const std::vector<std::uint8_t> truncated = [] {
    std::vector<std::uint8_t> bytes = lcmtf_test::encode(lcmtf_test::sampleTfMessage(2));
    bytes.resize(bytes.size() / 2);
    return bytes;
  }();
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  const tf_message_t request = lcmtf_test::sampleTfMessage(1);
  while (inbox.replies.empty() && std::chrono::steady_clock::now() < deadline) {
    lcm.publish("REQUEST", garbage.data(), static_cast<unsigned int>(garbage.size()));
    lcm.publish("REQUEST", truncated.data(), static_cast<unsigned int>(truncated.size()));
    lcm.publish("REQUEST", &request);
    lcm.handleTimeout(50);
  }
  ASSERT_FALSE(inbox.replies.empty()) << "the peer stopped answering after bad input";
  EXPECT_EQ(peer.waitForExit(5s), std::optional<int>(0));
}

}  // namespace
}  // namespace lcmtf
