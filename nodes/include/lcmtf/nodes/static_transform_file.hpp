#pragma once

#include <string>
#include <vector>

#include "lcmtf/nodes/static_transform_spec.hpp"

namespace lcmtf::nodes {

/// The keys a transform in a file may have: the flags' names with '_' for '-'.
const std::vector<std::string>& staticTransformFileKeys();

/// The transforms of a YAML file: a list of maps (or a map whose `transforms` key holds that
/// list) with the keys above. CommandLineError naming file, line and column otherwise.
std::vector<StaticTransformSpec> loadStaticTransformFile(const std::string& path);

/// The same for YAML text; `name` stands for the file in messages.
std::vector<StaticTransformSpec> parseStaticTransformYaml(const std::string& text,
                                                          const std::string& name);

}  // namespace lcmtf::nodes
