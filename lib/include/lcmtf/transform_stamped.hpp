#pragma once

#include <string>

#include "lcmtf/time.hpp"
#include "lcmtf/transform.hpp"

namespace lcmtf {

/// parent_frame_T_child_frame at `stamp`: maps data in child_frame into parent_frame.
struct TransformStamped {
  TimePoint stamp;
  std::string parent_frame;
  std::string child_frame;
  Transform transform;
};

}  // namespace lcmtf
