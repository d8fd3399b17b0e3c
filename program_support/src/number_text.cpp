#include "lcmtf/programs/number_text.hpp"

#include <cstdio>

namespace lcmtf::programs {

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace lcmtf::programs
