#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace lcmtf::urdf {

/// How large a robot description may be before it is refused unparsed (see the .cpp for why
/// these numbers): the XML parser and urdfdom overflow the stack on deep or long enough input.
struct DescriptionLimits {
  std::size_t max_nesting = 256;       ///< elements inside elements, the root counted as 1
  std::size_t max_links = 10'000;      ///< <link> elements
  std::size_t max_elements = 200'000;  ///< XML elements in all
};

/// What one pass over a description counts without parsing it, reading the markup as the XML
/// parser does: comments, CDATA, declarations and quoted attribute values hide no elements.
struct DescriptionShape {
  std::size_t deepest_nesting = 0;
  std::size_t elements = 0;
  std::size_t links = 0;
  /// Empty, or what the scan met that XML readers may read in different ways (an XML
  /// declaration with '>' in quotes, broken UTF-8), where it stopped: the counts are not to
  /// be trusted.
  std::string unreadable;
};

/// Counts the text's elements, <link> elements and deepest nesting in one linear pass.
DescriptionShape measureDescription(std::string_view text);

/// Throws UrdfError naming `source` and the first of `limits` the text exceeds, if any, in
/// the order nesting, links, elements; or naming what it cannot read.
void refuseOversizedDescription(std::string_view text, const std::string& source,
                                const DescriptionLimits& limits = {});

}  // namespace lcmtf::urdf
