#pragma once

// What a program can tell of a file's text before a parser reads it.

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

/// YAML's test of a text's first bytes for UTF-16 or UTF-32 rather than UTF-8: a byte order
/// mark, or a NUL among the first two bytes (the text then starts with an ASCII character).
inline bool isUtf16Or32(std::string_view text) {
  if (text.size() < 2) return false;
  const std::string_view first_two = text.substr(0, 2);
  return first_two == "\xFE\xFF" || first_two == "\xFF\xFE" || text[0] == '\0' || text[1] == '\0';
}

}  // namespace lcmtf::programs
