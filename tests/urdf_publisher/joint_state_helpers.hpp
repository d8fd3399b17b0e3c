#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lcmtf/joint_state_t.hpp"

namespace lcmtf_test {

/// A joint state with these names and positions (counts set from them, no velocities).
inline lcmtf::joint_state_t jointState(std::int64_t utime, const std::vector<std::string>& names,
                                       const std::vector<double>& positions) {
  lcmtf::joint_state_t state{};
  state.utime = utime;
  state.name = names;
  state.position = positions;
  state.num_joints = static_cast<std::int32_t>(names.size());
  state.num_positions = static_cast<std::int32_t>(positions.size());
  state.num_velocities = 0;
  state.num_efforts = 0;
  return state;
}

inline lcmtf::joint_state_t jointState(std::int64_t utime,
                                       const std::map<std::string, double>& positions) {
  std::vector<std::string> names;
  std::vector<double> values;
  for (const auto& [name, position] : positions) {
    names.push_back(name);
    values.push_back(position);
  }
  return jointState(utime, names, values);
}

/// Each named joint's position.
inline std::map<std::string, double> positionsOf(const lcmtf::joint_state_t& state) {
  std::map<std::string, double> positions;
  for (std::size_t i = 0; i < state.name.size() && i < state.position.size(); ++i) {
    positions[state.name[i]] = state.position[i];
  }
  return positions;
}

}  // namespace lcmtf_test
