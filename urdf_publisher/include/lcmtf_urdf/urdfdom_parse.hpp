#pragma once

#include <string>

#include <urdf_model/model.h>
#include <urdf_world/types.h>

namespace lcmtf::urdf {

/// urdfdom's model of `urdf`, or UrdfError naming `source` with urdfdom's own complaints,
/// which it would otherwise print through console_bridge.
::urdf::ModelInterfaceSharedPtr parseWithUrdfdom(const std::string& urdf,
                                                 const std::string& source);

}  // namespace lcmtf::urdf
