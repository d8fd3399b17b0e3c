#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace lcmtf::viewer {

/// `text` with A-Z made a-z, as host names, schemes and file extensions compare.
inline std::string asciiLowercase(std::string_view text) {
  std::string result(text);
  for (char& c : result) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return result;
}

}  // namespace lcmtf::viewer
