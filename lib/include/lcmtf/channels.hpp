#pragma once

#include <string>

namespace lcmtf {

/// The LCM channels lcmtf uses unless told otherwise.
inline constexpr const char* kTfChannel = "TF";
inline constexpr const char* kTfStaticChannel = "TF_STATIC";
inline constexpr const char* kTfStaticRequestChannel = "TF_STATIC_REQUEST";
inline constexpr const char* kJointStatesChannel = "JOINT_STATES";
inline constexpr const char* kRobotDescriptionChannel = "ROBOT_DESCRIPTION";
inline constexpr const char* kRobotDescriptionRequestChannel = "ROBOT_DESCRIPTION_REQUEST";

/// A stable name for this process as a sender: "program@host:pid".
std::string defaultAuthority();

}  // namespace lcmtf
