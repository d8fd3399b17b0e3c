#include <gtest/gtest.h>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/wire_decode.hpp"
#include "support/sample_messages.hpp"

namespace lcmtf {
namespace {

class Inbox {
 public:
  void onRawMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    channels.push_back(channel);
    tf_message_t message;
    const DecodeResult result = decodeMessage(buffer->data, buffer->data_size, message);
    if (result.ok) {
      messages.push_back(message);
    } else {
      errors.push_back(result.error);
    }
  }
  std::vector<std::string> channels;
  std::vector<tf_message_t> messages;
  std::vector<std::string> errors;
};

TEST(LcmMemq, TfMessagePublishedIsReceivedWithEveryField) {
  lcm::LCM lcm("memq://");
  ASSERT_TRUE(lcm.good());
  Inbox inbox;
  lcm.subscribe("TF", &Inbox::onRawMessage, &inbox);

  const tf_message_t sent = lcmtf_test::sampleTfMessage(4);
  ASSERT_EQ(lcm.publish("TF", &sent), 0);
  ASSERT_EQ(lcm.handleTimeout(1000), 1);

  ASSERT_EQ(inbox.messages.size(), 1u);
  EXPECT_EQ(inbox.channels, std::vector<std::string>{"TF"});
  lcmtf_test::expectEqual(inbox.messages[0], sent);
  const TransformStamped first = fromMessage(inbox.messages[0].transforms[0]);
  EXPECT_EQ(first.parent_frame, "parent_0");
  EXPECT_EQ(toUtime(first.stamp), sent.transforms[0].utime);
}

TEST(LcmMemq, ChannelsAreKeptApart) {
  lcm::LCM lcm("memq://");
  Inbox tf_inbox;
  Inbox static_inbox;
  lcm.subscribe("TF", &Inbox::onRawMessage, &tf_inbox);
  lcm.subscribe("TF_STATIC", &Inbox::onRawMessage, &static_inbox);

  const tf_message_t dynamic_batch = lcmtf_test::sampleTfMessage(1);
  const tf_message_t static_batch = lcmtf_test::sampleTfMessage(2);
  lcm.publish("TF", &dynamic_batch);
  lcm.publish("TF_STATIC", &static_batch);
  while (lcm.handleTimeout(0) > 0) {
  }
  ASSERT_EQ(tf_inbox.messages.size(), 1u);
  ASSERT_EQ(static_inbox.messages.size(), 1u);
  EXPECT_EQ(tf_inbox.messages[0].num_transforms, 1);
  EXPECT_EQ(static_inbox.messages[0].num_transforms, 2);
}

TEST(LcmMemq, GarbageOnTheChannelIsReportedNotDecoded) {
  lcm::LCM lcm("memq://");
  Inbox inbox;
  lcm.subscribe("TF", &Inbox::onRawMessage, &inbox);
  const std::vector<std::uint8_t> garbage{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  lcm.publish("TF", garbage.data(), static_cast<unsigned int>(garbage.size()));
  const tf_message_t good = lcmtf_test::sampleTfMessage(1);
  lcm.publish("TF", &good);
  while (lcm.handleTimeout(0) > 0) {
  }
  ASSERT_EQ(inbox.errors.size(), 1u);
  EXPECT_NE(inbox.errors[0].find("fingerprint"), std::string::npos) << inbox.errors[0];
  ASSERT_EQ(inbox.messages.size(), 1u);
  lcmtf_test::expectEqual(inbox.messages[0], good);
}

}  // namespace
}  // namespace lcmtf
