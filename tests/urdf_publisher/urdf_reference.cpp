#include "urdf_reference.hpp"

#include <tinyxml.h>

#include <set>
#include <sstream>
#include <stdexcept>

namespace lcmtf_test {

namespace {

Eigen::Vector3d vectorAttribute(const TiXmlElement* element, const char* attribute,
                                const Eigen::Vector3d& absent) {
  const char* text = element ? element->Attribute(attribute) : nullptr;
  if (!text) return absent;
  std::istringstream in(text);
  Eigen::Vector3d value;
  if (!(in >> value.x() >> value.y() >> value.z())) {
    throw std::runtime_error(std::string("cannot read ") + attribute + "=\"" + text + "\"");
  }
  return value;
}

double doubleAttribute(const TiXmlElement* element, const char* attribute, double absent) {
  double value = absent;
  if (element) element->QueryDoubleAttribute(attribute, &value);
  return value;
}

std::string linkOf(const TiXmlElement* joint, const char* which) {
  const TiXmlElement* element = joint->FirstChildElement(which);
  if (!element || !element->Attribute("link")) throw std::runtime_error("joint without a link");
  return element->Attribute("link");
}

}  // namespace

ReferenceRobot::ReferenceRobot(const std::string& path) {
  TiXmlDocument document;
  if (!document.LoadFile(path)) throw std::runtime_error("cannot read " + path);
  const TiXmlElement* robot = document.FirstChildElement("robot");
  if (!robot) throw std::runtime_error(path + " has no <robot>");
  for (const TiXmlElement* link = robot->FirstChildElement("link"); link;
       link = link->NextSiblingElement("link")) {
    links_.push_back(link->Attribute("name"));
  }
  for (const TiXmlElement* element = robot->FirstChildElement("joint"); element;
       element = element->NextSiblingElement("joint")) {
    ReferenceJoint joint;
    joint.name = element->Attribute("name");
    joint.type = element->Attribute("type");
    joint.parent = linkOf(element, "parent");
    joint.child = linkOf(element, "child");
    const TiXmlElement* origin = element->FirstChildElement("origin");
    joint.xyz = vectorAttribute(origin, "xyz", Eigen::Vector3d::Zero());
    joint.rpy = vectorAttribute(origin, "rpy", Eigen::Vector3d::Zero());
    joint.axis =
        vectorAttribute(element->FirstChildElement("axis"), "xyz", Eigen::Vector3d::UnitX());
    if (const TiXmlElement* limit = element->FirstChildElement("limit")) {
      joint.has_limits = joint.type != "continuous";
      joint.lower = doubleAttribute(limit, "lower", 0.0);
      joint.upper = doubleAttribute(limit, "upper", 0.0);
    }
    if (const TiXmlElement* mimic = element->FirstChildElement("mimic")) {
      joint.mimic_leader = mimic->Attribute("joint");
      joint.multiplier = doubleAttribute(mimic, "multiplier", 1.0);
      joint.offset = doubleAttribute(mimic, "offset", 0.0);
    }
    by_name_[joint.name] = joints_.size();
    joint_to_child_[joint.child] = joints_.size();
    joints_.push_back(joint);
  }
  for (const std::string& link : links_) {
    if (!joint_to_child_.count(link)) root_ = link;
  }
}

std::vector<std::string> ReferenceRobot::links() const { return links_; }

const ReferenceJoint& ReferenceRobot::jointToChild(const std::string& child) const {
  const auto found = joint_to_child_.find(child);
  if (found == joint_to_child_.end()) throw std::runtime_error("no joint to " + child);
  return joints_[found->second];
}

Eigen::Isometry3d ReferenceRobot::parentTChild(const ReferenceJoint& joint, double position) {
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(joint.rpy.z(), Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(joint.rpy.y(), Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(joint.rpy.x(), Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  Eigen::Isometry3d parent_T_child = Eigen::Isometry3d::Identity();
  parent_T_child.linear() = rotation;
  parent_T_child.translation() = joint.xyz;
  const Eigen::Vector3d axis = joint.axis.normalized();
  if (joint.type == "revolute" || joint.type == "continuous") {
    parent_T_child.linear() = rotation * Eigen::AngleAxisd(position, axis).toRotationMatrix();
  } else if (joint.type == "prismatic") {
    parent_T_child.translation() += rotation * (axis * position);
  }
  return parent_T_child;
}

double ReferenceRobot::positionOf(const ReferenceJoint& joint,
                                  const std::map<std::string, double>& driven) const {
  if (!joint.movable()) return 0.0;
  if (joint.mimic_leader.empty()) {
    const auto found = driven.find(joint.name);
    return found == driven.end() ? 0.0 : found->second;
  }
  const ReferenceJoint& leader = joints_[by_name_.at(joint.mimic_leader)];
  return joint.multiplier * positionOf(leader, driven) + joint.offset;
}

Eigen::Isometry3d ReferenceRobot::rootTLink(const std::string& link,
                                            const std::map<std::string, double>& driven) const {
  Eigen::Isometry3d root_T_link = Eigen::Isometry3d::Identity();
  for (std::string current = link; current != root_;) {
    const ReferenceJoint& joint = jointToChild(current);
    root_T_link = parentTChild(joint, positionOf(joint, driven)) * root_T_link;
    current = joint.parent;
  }
  return root_T_link;
}

}  // namespace lcmtf_test
