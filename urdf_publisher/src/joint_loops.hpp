#pragma once

#include <tinyxml.h>

#include <string>

namespace lcmtf::urdf {

/// Throws UrdfError naming `source` when the <joint> elements of the URDF document form a loop
/// or give a link two parents. Checked on the XML before urdfdom sees it: urdfdom leaks the
/// links of a loop. A document that is not a <robot> passes, for urdfdom to explain.
void refuseJointLoops(const TiXmlDocument& urdf, const std::string& source);

}  // namespace lcmtf::urdf
