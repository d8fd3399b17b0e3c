#pragma once

#include <string>

namespace lcmtf::programs {

/// A number as printf's %g writes it: short, exact enough for messages ("0.548", "1e-09").
std::string formatNumber(double value);

}  // namespace lcmtf::programs
