#pragma once

#include "lcmtf/programs/closest_names.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/programs/lcm_connection.hpp"
#include "lcmtf/programs/program_authority.hpp"
#include "lcmtf/programs/roll_pitch_yaw.hpp"
#include "lcmtf/programs/saturating.hpp"

namespace lcmtf::nodes {

// The tools call what every program shares by its short name.
using namespace lcmtf::programs;

}  // namespace lcmtf::nodes
