#include "joint_loops.hpp"

#include <tinyxml.h>

#include <map>
#include <set>
#include <vector>

#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {

namespace {

const char* linkOf(const TiXmlElement& joint, const char* which) {
  const TiXmlElement* element = joint.FirstChildElement(which);
  return element ? element->Attribute("link") : nullptr;
}

struct Edge {
  std::string parent;
  std::string joint;
};

// "joints 'ab' (a -> b), 'bc' (b -> c), 'ca' (c -> a) form a loop", from parent to child.
std::string describeLoop(const std::map<std::string, Edge>& parent_of, const std::string& start) {
  std::vector<std::string> upward;
  std::string link = start;
  do {
    const Edge& edge = parent_of.at(link);
    upward.push_back("'" + edge.joint + "' (" + edge.parent + " -> " + link + ")");
    link = edge.parent;
  } while (link != start);
  std::string text = "joints ";
  for (auto joint = upward.rbegin(); joint != upward.rend(); ++joint) {
    text += (joint == upward.rbegin() ? "" : ", ") + *joint;
  }
  return text + " form a loop";
}

}  // namespace

void refuseJointLoops(const TiXmlDocument& urdf, const std::string& source) {
  const TiXmlElement* robot = urdf.Error() ? nullptr : urdf.FirstChildElement("robot");
  if (!robot) return;

  std::map<std::string, Edge> parent_of;
  for (const TiXmlElement* joint = robot->FirstChildElement("joint"); joint;
       joint = joint->NextSiblingElement("joint")) {
    const char* name = joint->Attribute("name");
    const char* parent = linkOf(*joint, "parent");
    const char* child = linkOf(*joint, "child");
    if (!name || !parent || !child) continue;  // urdfdom says what is missing
    const auto [other, inserted] = parent_of.emplace(child, Edge{parent, name});
    if (!inserted) {
      throw UrdfError(source + ": link '" + child + "' is the child of two joints, '" +
                      other->second.joint + "' and '" + name + "'");
    }
  }
  std::set<std::string> cleared;  // links known to lead up to a root
  for (const auto& [start, edge] : parent_of) {
    std::set<std::string> path;
    std::string link = start;
    while (!cleared.count(link) && parent_of.count(link)) {
      if (!path.insert(link).second) throw UrdfError(source + ": " + describeLoop(parent_of, link));
      link = parent_of.at(link).parent;
    }
    cleared.insert(path.begin(), path.end());
  }
}

}  // namespace lcmtf::urdf
