#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include <lcm/lcm-cpp.hpp>

namespace lcmtf::detail {

/// An LCM on `url` ("" for LCM's default), or std::runtime_error naming the URL.
inline std::unique_ptr<lcm::LCM> openLcm(const std::string& url) {
  auto lcm = std::make_unique<lcm::LCM>(url);
  if (!lcm->good()) throw std::runtime_error("cannot open LCM at '" + url + "'");
  return lcm;
}

}  // namespace lcmtf::detail
