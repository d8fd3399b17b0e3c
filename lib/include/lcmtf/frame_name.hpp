#pragma once

#include <string_view>

namespace lcmtf {

/// A frame's name as the buffer stores it: one leading '/' (tf1's global prefix) removed.
constexpr std::string_view canonicalFrameName(std::string_view name) {
  if (!name.empty() && name.front() == '/') name.remove_prefix(1);
  return name;
}

}  // namespace lcmtf
