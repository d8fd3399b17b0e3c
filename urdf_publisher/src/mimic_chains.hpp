#pragma once

#include <string>
#include <vector>

#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// Sets resolved_mimic on every mimic joint of `robot`, composing relations along the chain
/// to a joint that follows no other. Throws UrdfError for a leader that is missing or cannot
/// move, for a loop of mimic joints, and for a chain whose composed values overflow.
void resolveMimicChains(RobotModel& robot);

}  // namespace lcmtf::urdf
