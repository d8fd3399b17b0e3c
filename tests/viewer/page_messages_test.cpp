// parsePageMessage: what a page may send, and a clear refusal naming the field otherwise.
#include "lcmtf_viewer/page_messages.hpp"

#include <gtest/gtest.h>

namespace lcmtf::viewer {
namespace {

template <class Message>
Message parsed(std::string_view text) {
  auto result = parsePageMessage(text);
  if (const std::string* why = std::get_if<std::string>(&result)) {
    ADD_FAILURE() << text << ": " << *why;
    return {};
  }
  return std::get<Message>(std::get<PageMessage>(result));
}

std::string refusal(std::string_view text) {
  auto result = parsePageMessage(text);
  if (const std::string* why = std::get_if<std::string>(&result)) return *why;
  ADD_FAILURE() << text << " was accepted";
  return {};
}

TEST(PageMessages, ReadsAckViewAndJoints) {
  EXPECT_EQ(parsed<AckMessage>(R"({"type":"ack","seq":12})").seq, 12);
  const auto live = parsed<ViewMessage>(R"({"type":"view","fixed_frame":"odom","time":null})");
  EXPECT_EQ(live.fixed_frame, "odom");
  EXPECT_FALSE(live.time_us.has_value());
  const auto paused =
      parsed<ViewMessage>(R"({"type":"view","fixed_frame":"","time":1795334869973768})");
  EXPECT_EQ(paused.time_us, 1795334869973768);
  const auto joints =
      parsed<JointsMessage>(R"({"type":"joints","enabled":true,"positions":{"a":0.5,"b":-1}})");
  EXPECT_TRUE(joints.enabled);
  EXPECT_EQ(joints.positions, (std::map<std::string, double>{{"a", 0.5}, {"b", -1.0}}));
  EXPECT_FALSE(parsed<JointsMessage>(R"({"type":"joints","enabled":false})").enabled);
}

TEST(PageMessages, RefusesWhatIsNotAMessageWithAReason) {
  EXPECT_EQ(refusal("not json"), "the message is not JSON");
  EXPECT_EQ(refusal(""), "the message is not JSON");
  EXPECT_EQ(refusal(R"({"type":"ack","seq":1)"), "the message is not JSON");
  EXPECT_EQ(refusal("[1,2]"), "the message is an array, not an object");
  EXPECT_EQ(refusal("42"), "the message is a number, not an object");
  EXPECT_EQ(refusal(R"({"seq":1})"), "the message has no \"type\" string");
  EXPECT_EQ(refusal(R"({"type":7})"), "the message has no \"type\" string");
  EXPECT_EQ(refusal(R"({"type":"launch"})"), "unknown message type 'launch'");
  EXPECT_EQ(refusal(R"({"type":"ack","seq":NaN})"), "the message is not JSON");
}

TEST(PageMessages, RefusesFieldsOfTheWrongTypeOrRangeNamingThem) {
  EXPECT_EQ(refusal(R"({"type":"ack"})"), "ack.seq: missing");
  EXPECT_EQ(refusal(R"({"type":"ack","seq":"3"})"), "ack.seq: a string, not a whole number >= 0");
  EXPECT_EQ(refusal(R"({"type":"ack","seq":-1})"), "ack.seq: a number, not a whole number >= 0");
  EXPECT_EQ(refusal(R"({"type":"ack","seq":1.5})"),
            "ack.seq: a number with a fraction, not a whole number >= 0");
  EXPECT_EQ(refusal(R"({"type":"view"})"), "view.fixed_frame: missing");
  EXPECT_EQ(refusal(R"({"type":"view","fixed_frame":["odom"]})"),
            "view.fixed_frame: an array, not a string");
  EXPECT_EQ(refusal(R"({"type":"view","fixed_frame":"odom","time":"yesterday"})"),
            "view.time: a string, not null (live) or a stamp in microseconds > 0");
  EXPECT_EQ(refusal(R"({"type":"view","fixed_frame":"odom","time":-5})"),
            "view.time: a number, not null (live) or a stamp in microseconds > 0");
  EXPECT_EQ(refusal(R"({"type":"joints","positions":{}})"), "joints.enabled: missing");
  EXPECT_EQ(refusal(R"({"type":"joints","enabled":1})"),
            "joints.enabled: a number, not true or false");
  EXPECT_EQ(refusal(R"({"type":"joints","enabled":true,"positions":[1]})"),
            "joints.positions: an array, not an object");
  EXPECT_EQ(refusal(R"({"type":"joints","enabled":true,"positions":{"a":"1"}})"),
            "joints.positions['a']: a string, not a finite number");
  EXPECT_EQ(refusal(R"({"type":"joints","enabled":true,"positions":{"a":1e999}})"),
            "the message is not JSON");
}

TEST(PageMessages, RefusesOversizedAndDeeplyNestedMessagesBeforeParsing) {
  const std::string huge =
      R"({"type":"view","fixed_frame":")" + std::string(kMaxPageMessageBytes, 'x') + R"("})";
  EXPECT_EQ(refusal(huge), "the message is " + std::to_string(huge.size()) + " bytes, more than " +
                               std::to_string(kMaxPageMessageBytes));
  EXPECT_EQ(refusal(std::string(20000, '[') + std::string(20000, ']')),
            "the message nests deeper than 8 levels");
  // Brackets inside strings are not nesting.
  EXPECT_EQ(parsed<ViewMessage>(R"({"type":"view","fixed_frame":"[[[[[[[[[[[[\"]]"})").fixed_frame,
            "[[[[[[[[[[[[\"]]");
  const std::string long_name(kMaxFrameNameBytes + 1, 'f');
  EXPECT_EQ(refusal(R"({"type":"view","fixed_frame":")" + long_name + R"("})"),
            "view.fixed_frame: longer than 1024 bytes");
}

TEST(PageMessages, RefusesTooManyJointPositions) {
  std::string text = R"({"type":"joints","enabled":true,"positions":{)";
  for (std::size_t i = 0; i <= kMaxJointPositions; ++i) {
    text += (i ? "," : "") + std::string("\"j") + std::to_string(i) + "\":0";
  }
  text += "}}";
  EXPECT_EQ(refusal(text), "joints.positions: more than 1000 joints");
}

}  // namespace
}  // namespace lcmtf::viewer
