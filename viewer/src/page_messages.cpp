#include "lcmtf_viewer/page_messages.hpp"

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

namespace lcmtf::viewer {

namespace {

using nlohmann::json;

// The deepest nesting of arrays and objects, read without parsing, so that no parser or
// destructor recurses through what a page sent.
std::size_t deepestNesting(std::string_view text) {
  std::size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    case json::value_t::number_float:
      return "a number with a fraction";
    default:
      return "a number";
  }
}

using Refusal = std::string;

std::string shortened(const std::string& name) {
  return name.size() <= 64 ? name : name.substr(0, 64) + "...";
}

std::variant<PageMessage, Refusal> ack(const json& message) {
  const auto seq = message.find("seq");
  if (seq == message.end()) return Refusal("ack.seq: missing");
  if (!seq->is_number_integer() || seq->get<std::int64_t>() < 0) {
    return Refusal("ack.seq: " + describe(*seq) + ", not a whole number >= 0");
  }
  return AckMessage{seq->get<std::int64_t>()};
}

std::variant<PageMessage, Refusal> view(const json& message) {
  ViewMessage view;
  const auto frame = message.find("fixed_frame");
  if (frame == message.end()) return Refusal("view.fixed_frame: missing");
  if (!frame->is_string())
    return Refusal("view.fixed_frame: " + describe(*frame) + ", not a string");
  view.fixed_frame = frame->get<std::string>();
  if (view.fixed_frame.size() > kMaxFrameNameBytes) {
    return Refusal("view.fixed_frame: longer than " + std::to_string(kMaxFrameNameBytes) +
                   " bytes");
  }
  const auto time = message.find("time");
  if (time != message.end() && !time->is_null()) {
    if (!time->is_number_integer() || time->get<std::int64_t>() <= 0) {
      return Refusal("view.time: " + describe(*time) +
                     ", not null (live) or a stamp in microseconds > 0");
    }
    view.time_us = time->get<std::int64_t>();
  }
  return view;
}

std::variant<PageMessage, Refusal> joints(const json& message) {
  JointsMessage joints;
  const auto enabled = message.find("enabled");
  if (enabled == message.end()) return Refusal("joints.enabled: missing");
  if (!enabled->is_boolean())
    return Refusal("joints.enabled: " + describe(*enabled) + ", not true or false");
  joints.enabled = enabled->get<bool>();
  const auto positions = message.find("positions");
  if (positions == message.end()) return joints;
  if (!positions->is_object()) {
    return Refusal("joints.positions: " + describe(*positions) + ", not an object");
  }
  if (positions->size() > kMaxJointPositions) {
    return Refusal("joints.positions: more than " + std::to_string(kMaxJointPositions) + " joints");
  }
  for (const auto& [name, value] : positions->items()) {
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
      return Refusal("joints.positions['" + shortened(name) + "']: " + describe(value) +
                     ", not a finite number");
    }
    joints.positions[name] = value.get<double>();
  }
  return joints;
}

}  // namespace

std::variant<PageMessage, std::string> parsePageMessage(std::string_view text) {
  if (text.size() > kMaxPageMessageBytes) {
    return "the message is " + std::to_string(text.size()) + " bytes, more than " +
           std::to_string(kMaxPageMessageBytes);
  }
  if (deepestNesting(text) > kMaxNesting) {
    return "the message nests deeper than " + std::to_string(kMaxNesting) + " levels";
  }
  const json message = json::parse(text.begin(), text.end(), nullptr, false);
  if (message.is_discarded()) return "the message is not JSON";
  if (!message.is_object()) return "the message is " + describe(message) + ", not an object";
  const auto type = message.find("type");
  if (type == message.end() || !type->is_string()) return "the message has no \"type\" string";
  const std::string& kind = type->get_ref<const std::string&>();
  std::variant<PageMessage, Refusal> parsed;
  if (kind == "ack") {
    parsed = ack(message);
  } else if (kind == "view") {
    parsed = view(message);
  } else if (kind == "joints") {
    parsed = joints(message);
  } else {
    return "unknown message type '" + kind.substr(0, 64) + "'";
  }
  return parsed;
}

}  // namespace lcmtf::viewer
