#pragma once

#include <algorithm>
#include <cstddef>
#include <string_view>

namespace lcmtf::programs {

/// Where a byte of a text is, as editors number it: lines and columns from 1, columns in bytes.
struct TextPosition {
  std::size_t line = 1;
  std::size_t column = 1;
};

/// The position of byte `offset` of `text`.
inline TextPosition positionOf(std::string_view text, std::size_t offset) {
  const std::string_view before = text.substr(0, offset);
  const std::size_t line_start = before.rfind('\n');
  return TextPosition{
      1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n')),
      1 + (line_start == std::string_view::npos ? offset : offset - line_start - 1)};
}

}  // namespace lcmtf::programs
