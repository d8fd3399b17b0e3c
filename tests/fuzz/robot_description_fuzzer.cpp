// libFuzzer target: text as a robot description from the network or a file, through the whole
// parse: the limits scan, TinyXML, urdfdom and the model built from it. Any crash, sanitizer
// report or escaped exception is a bug; so is a document that TinyXML reads deeper, or with
// more elements or links, than the scan counted, since the limits then protect nothing.
#include <tinyxml.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "lcmtf_urdf/description_limits.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace {

using lcmtf::urdf::DescriptionLimits;
using lcmtf::urdf::DescriptionShape;

// The elements TinyXML built, a partial tree after an error included, walked without recursion.
DescriptionShape measureParsed(const TiXmlDocument& document) {
  DescriptionShape shape;
  std::vector<std::pair<const TiXmlNode*, std::size_t>> pending{{&document, 0}};
  while (!pending.empty()) {
    const auto [node, depth] = pending.back();
    pending.pop_back();
    for (const TiXmlElement* child = node->FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      ++shape.elements;
      if (child->ValueStr() == "link") ++shape.links;
      shape.deepest_nesting = std::max(shape.deepest_nesting, depth + 1);
      pending.emplace_back(child, depth + 1);
    }
  }
  return shape;
}

bool withinLimits(const DescriptionShape& shape) {
  const DescriptionLimits limits;
  return shape.unreadable.empty() && shape.deepest_nesting <= limits.max_nesting &&
         shape.links <= limits.max_links && shape.elements <= limits.max_elements;
}

void checkTheScanCountsAllThatTinyXmlReads(const std::string& text) {
  const DescriptionShape counted = lcmtf::urdf::measureDescription(text);
  if (!withinLimits(counted)) return;  // refused before any parser sees it
  TiXmlDocument document;
  document.Parse(text.c_str());
  const DescriptionShape parsed = measureParsed(document);
  if (parsed.deepest_nesting > counted.deepest_nesting || parsed.elements > counted.elements ||
      parsed.links > counted.links) {
    std::fprintf(stderr,
                 "the scan counted %zu deep, %zu elements, %zu links; TinyXML read %zu deep, "
                 "%zu elements, %zu links\n",
                 counted.deepest_nesting, counted.elements, counted.links, parsed.deepest_nesting,
                 parsed.elements, parsed.links);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  checkTheScanCountsAllThatTinyXmlReads(text);
  try {
    lcmtf::urdf::parseRobotModel(text, "fuzz");
  } catch (const lcmtf::urdf::UrdfError&) {
  }
  return 0;
}
