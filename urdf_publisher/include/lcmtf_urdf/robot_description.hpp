#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/channels.hpp"
#include "lcmtf/robot_description_t.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

/// The robot_description_t carrying `robot`'s URDF text, signed by `authority`.
robot_description_t makeRobotDescription(const RobotModel& robot, const std::string& authority,
                                         TimePoint sent = now());

/// Where a program that has no URDF file gets its robot from.
struct DescriptionWaitOptions {
  std::string channel = kRobotDescriptionChannel;
  std::string request_channel = kRobotDescriptionRequestChannel;
  std::string authority = defaultAuthority();                ///< signs the requests
  Duration request_period = std::chrono::seconds(1);         ///< asks again this often
  Duration timeout = Duration::zero();                       ///< gives up after this; 0: never
  std::function<void(const std::string& message)> reporter;  ///< descriptions refused, and why
};

/// What a wait for a description heard.
struct DescriptionWaitStatistics {
  std::uint64_t received = 0;  ///< messages on the channel, refused ones included
  std::uint64_t refused = 0;   ///< messages that did not decode or did not make a valid robot
};

/// The first description on options.channel that makes a valid robot, asking for one at once
/// and every request_period; refused ones are reported (each kind once) and counted in
/// `statistics` when given. Nothing once `stop` is set or the timeout has passed.
std::optional<RobotModel> waitForRobotDescription(lcm::LCM& lcm,
                                                  const DescriptionWaitOptions& options,
                                                  const std::atomic<bool>& stop,
                                                  DescriptionWaitStatistics* statistics = nullptr);

}  // namespace lcmtf::urdf
