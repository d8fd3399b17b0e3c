#pragma once

#include <tinyxml.h>

#include <string>

namespace lcmtf::urdf {

/// Parses the text into `document`, or throws UrdfError naming `source` when it is not
/// well-formed XML: what is wrong and, for a syntax error, its line and column, which
/// urdfdom's own messages leave out. Text of only whitespace is left for urdfdom to explain.
void parseXmlOrRefuse(const std::string& text, const std::string& source, TiXmlDocument& document);

}  // namespace lcmtf::urdf
