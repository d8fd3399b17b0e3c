#pragma once

#include <string>

namespace lcmtf::urdf {

/// Throws UrdfError naming `source` when the text is not well-formed XML: what is wrong and, for
/// a syntax error, its line and column, which urdfdom's own messages leave out.
void refuseMalformedXml(const std::string& text, const std::string& source);

}  // namespace lcmtf::urdf
