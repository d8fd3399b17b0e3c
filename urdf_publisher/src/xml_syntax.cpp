#include "xml_syntax.hpp"

#include <algorithm>

#include "lcmtf/printable.hpp"
#include "lcmtf/programs/plain_text.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

namespace {

// The first characters of the text's first line, to show what was given instead of XML.
std::string opening(const std::string& text, std::size_t from) {
  const std::size_t end = std::min({text.find_first_of("\r\n", from), text.size(), from + 24});
  return printable(std::string_view(text).substr(from, end - from));
}

}  // namespace

void parseXmlOrRefuse(const std::string& text, const std::string& source, TiXmlDocument& document) {
  std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  start = text.find_first_not_of(" \t\r\n", start);
  if (start == std::string::npos) return;
  if (text[start] != '<') {
    throw UrdfError(source + ": not XML: a URDF starts with '<', this starts with '" +
                    opening(text, start) + "'");
  }
  // TinyXML and urdfdom read the text up to its first NUL byte: what follows would be lost.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
    const programs::TextPosition at = programs::positionOf(text, nul);
    throw UrdfError(source + ": not XML: a NUL byte at line " + std::to_string(at.line) +
                    ", column " + std::to_string(at.column) + " (XML text has none)");
  }
  document.Parse(text.c_str());
  if (!document.Error()) return;
  std::string where;
  if (document.ErrorRow() > 0) {
    where = " at line " + std::to_string(document.ErrorRow()) + ", column " +
            std::to_string(document.ErrorCol());
  }
  throw UrdfError(source + ": malformed XML" + where + ": " + document.ErrorDesc());
}

}  // namespace lcmtf::urdf
