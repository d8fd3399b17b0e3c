#pragma once

#include <string>

#include "lcmtf/time.hpp"

namespace lcmtf {

/// Data of any type with the frame it is expressed in and the time it was valid.
template <class T>
struct Stamped {
  T data;
  std::string frame_id;
  TimePoint stamp;
};

/// The accessors the library reads stamped data through (also used by MessageFilter setups).
template <class T>
const std::string& frameOf(const Stamped<T>& stamped) {
  return stamped.frame_id;
}
template <class T>
TimePoint stampOf(const Stamped<T>& stamped) {
  return stamped.stamp;
}

}  // namespace lcmtf
