#include "xml_syntax.hpp"

#include <tinyxml.h>

#include <cctype>

#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

namespace {

// The first characters of the text, printable, to show what was given instead of XML.
std::string opening(const std::string& text, std::size_t from) {
  std::string shown;
  for (std::size_t i = from; i < text.size() && shown.size() < 24; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n' || c == '\r') break;
    shown += std::isprint(c) ? static_cast<char>(c) : '.';
  }
  return shown;
}

}  // namespace

void refuseMalformedXml(const std::string& text, const std::string& source) {
  std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  start = text.find_first_not_of(" \t\r\n", start);
  if (start == std::string::npos) return;
  if (text[start] != '<') {
    throw UrdfError(source + ": not XML: a URDF starts with '<', this starts with '" +
                    opening(text, start) + "'");
  }
  TiXmlDocument document;
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
