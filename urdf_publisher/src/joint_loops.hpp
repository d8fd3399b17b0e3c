#pragma once

#include <string>

namespace lcmtf::urdf {

/// Throws UrdfError naming `source` when the <joint> elements of the URDF text form a loop or
/// give a link two parents. Checked on the XML before urdfdom sees it: urdfdom leaks the
/// links of a loop. Text that is not a <robot> document passes, for urdfdom to explain.
void refuseJointLoops(const std::string& urdf, const std::string& source);

}  // namespace lcmtf::urdf
