#include "lcmtf_viewer/robot_view.hpp"

#include <cctype>
#include <cmath>
#include <map>

#include <urdf_model/model.h>

#include "ascii_lowercase.hpp"
#include "lcmtf_urdf/urdfdom_parse.hpp"

namespace lcmtf::viewer {

namespace {

using nlohmann::json;

json poseArray(const ::urdf::Pose& pose) {
  return json::array({pose.position.x, pose.position.y, pose.position.z, pose.rotation.x,
                      pose.rotation.y, pose.rotation.z, pose.rotation.w});
}

// urdfdom refuses what is not a number, but a visual must never reach the page with one.
bool allFinite(const json& value) {
  if (value.is_number_float()) return std::isfinite(value.get<double>());
  if (value.is_array() || value.is_object()) {
    for (const json& item : value) {
      if (!allFinite(item)) return false;
    }
  }
  return true;
}

std::string lowerExtension(const std::filesystem::path& path) {
  return asciiLowercase(path.extension().string());
}

class ViewBuilder {
 public:
  ViewBuilder(const ::urdf::ModelInterface& urdf, const MeshSearch& search)
      : urdf_(urdf), search_(search) {}

  json link(const std::string& name) {
    json visuals = json::array();
    const ::urdf::LinkConstSharedPtr link = urdf_.getLink(name);
    if (link) {
      for (const ::urdf::VisualSharedPtr& visual : link->visual_array) {
        if (!visual || !visual->geometry) continue;
        json geometry = this->geometry(name, *visual->geometry);
        if (geometry.is_null()) continue;
        json drawn = {{"origin", poseArray(visual->origin)},
                      {"geometry", std::move(geometry)},
                      {"color", color(*visual)}};
        if (!allFinite(drawn)) {
          warnings_.push_back("link '" + name + "': a visual with a number that is not finite");
          continue;
        }
        visuals.push_back(std::move(drawn));
      }
    }
    return {{"name", name}, {"visuals", visuals}};
  }

  RobotView finish(json robot) {
    robot["warnings"] = warnings_;
    return RobotView{std::move(robot), std::move(meshes_), std::move(warnings_)};
  }

 private:
  json geometry(const std::string& link, const ::urdf::Geometry& geometry) {
    switch (geometry.type) {
      case ::urdf::Geometry::BOX: {
        const auto& box = static_cast<const ::urdf::Box&>(geometry);
        return {{"kind", "box"}, {"size", {box.dim.x, box.dim.y, box.dim.z}}};
      }
      case ::urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const ::urdf::Cylinder&>(geometry);
        return {{"kind", "cylinder"}, {"radius", cylinder.radius}, {"length", cylinder.length}};
      }
      case ::urdf::Geometry::SPHERE:
        return {{"kind", "sphere"},
                {"radius", static_cast<const ::urdf::Sphere&>(geometry).radius}};
      case ::urdf::Geometry::MESH:
        return mesh(link, static_cast<const ::urdf::Mesh&>(geometry));
    }
    warnings_.push_back("link '" + link + "': a geometry of unknown kind is not drawn");
    return nullptr;
  }

  json mesh(const std::string& link, const ::urdf::Mesh& mesh) {
    const auto located = locateMesh(mesh.filename, search_);
    if (const std::string* why = std::get_if<std::string>(&located)) {
      warnings_.push_back("link '" + link + "': mesh " + *why);
      return nullptr;
    }
    const std::filesystem::path& file = std::get<std::filesystem::path>(located);
    const std::string extension = lowerExtension(file);
    if (extension != ".stl" && extension != ".dae") {
      warnings_.push_back("link '" + link + "': mesh '" + mesh.filename +
                          "' is neither STL nor COLLADA, which are what is drawn");
      return nullptr;
    }
    auto [known, added] = mesh_indices_.emplace(file, meshes_.size());
    if (added) meshes_.push_back(file);
    return {{"kind", "mesh"},
            {"url", meshUrlPath(known->second, file)},
            {"format", extension.substr(1)},
            {"scale", {mesh.scale.x, mesh.scale.y, mesh.scale.z}}};
  }

  json color(const ::urdf::Visual& visual) const {
    ::urdf::MaterialSharedPtr material = visual.material;
    if (!material && !visual.material_name.empty()) {
      material = urdf_.getMaterial(visual.material_name);
    }
    if (!material) return nullptr;
    const ::urdf::Color& c = material->color;
    if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b) || !std::isfinite(c.a)) {
      return nullptr;
    }
    // urdfdom keeps colours as floats: 0.8 would come out as 0.800000011920929.
    auto decimal = [](float channel) { return std::round(double{channel} * 1e6) / 1e6; };
    return json::array({decimal(c.r), decimal(c.g), decimal(c.b), decimal(c.a)});
  }

  const ::urdf::ModelInterface& urdf_;
  const MeshSearch& search_;
  std::vector<std::filesystem::path> meshes_;
  std::map<std::filesystem::path, std::size_t> mesh_indices_;
  std::vector<std::string> warnings_;
};

json joint(const urdf::MovableJoint& movable) {
  json joint = {{"name", movable.name},
                {"type", urdf::toString(movable.motion)},
                {"parent", movable.parent_link},
                {"child", movable.child_link},
                {"lower", movable.limits ? movable.limits->lower : -M_PI},
                {"upper", movable.limits ? movable.limits->upper : M_PI},
                {"mimic", nullptr},
                {"slider", !movable.mimic.has_value()}};
  if (movable.mimic) {
    joint["mimic"] = {{"leader", movable.mimic->leader},
                      {"multiplier", movable.mimic->multiplier},
                      {"offset", movable.mimic->offset}};
  }
  return joint;
}

json fixedJoint(const std::string& name, const std::string& type, const std::string& parent,
                const std::string& child) {
  return {{"name", name}, {"type", type}, {"parent", parent}, {"child", child},
          {"lower", 0.0}, {"upper", 0.0}, {"mimic", nullptr}, {"slider", false}};
}

}  // namespace

RobotView makeRobotView(const urdf::RobotModel& model, const MeshSearch& search) {
  const ::urdf::ModelInterfaceSharedPtr urdf = urdf::parseWithUrdfdom(model.urdf, model.source);
  ViewBuilder builder(*urdf, search);
  json links = json::array();
  for (const std::string& name : model.links) links.push_back(builder.link(name));
  json joints = json::array();
  for (const urdf::MovableJoint& movable : model.movable_joints) joints.push_back(joint(movable));
  for (const urdf::FixedJoint& fixed : model.fixed_joints) {
    joints.push_back(fixedJoint(fixed.name, "fixed", fixed.parent_link, fixed.child_link));
  }
  for (const urdf::UnsupportedJoint& other : model.unsupported_joints) {
    joints.push_back(fixedJoint(other.name, other.type, other.parent_link, other.child_link));
  }
  return builder.finish({{"name", model.name},
                         {"source", model.source},
                         {"root_link", model.root_link},
                         {"links", links},
                         {"joints", joints}});
}

std::string meshUrlPath(std::size_t index, const std::filesystem::path& file) {
  std::string name = file.filename().string();
  for (char& c : name) {
    const bool plain =
        std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
    if (!plain) c = '_';
  }
  while (name.find("..") != std::string::npos) name.replace(name.find(".."), 2, "_.");
  return "/mesh/" + std::to_string(index) + "/" + name;
}

}  // namespace lcmtf::viewer
