#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace lcmtf::viewer {

/// `value` as compact JSON text; bytes that are not UTF-8 (a frame name off the network may
/// hold any) become U+FFFD instead of an exception.
inline std::string jsonText(const nlohmann::json& value) {
  return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace lcmtf::viewer
