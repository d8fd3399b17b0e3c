#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "lcmtf/printable.hpp"

namespace lcmtf_fuzz {

/// Stops the fuzzer on a broken check, saying which and showing up to 300 bytes of what broke
/// it, escaped.
[[noreturn]] inline void fail(const char* what, std::string_view detail) {
  const std::string shown = lcmtf::printable(detail.substr(0, 300));
  std::fprintf(stderr, "%s: %s\n", what, shown.c_str());
  std::abort();
}

}  // namespace lcmtf_fuzz
