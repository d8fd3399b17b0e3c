#pragma once

#include <cstdio>
#include <string>

namespace lcmtf::urdf {

/// A number as printf's %g writes it: short, exact enough for messages ("0.548", "1e-09").
inline std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace lcmtf::urdf
