#include "lcmtf/nodes/static_transform_spec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

#include "lcmtf/frame_name.hpp"
#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/sendable_names.hpp"

namespace lcmtf::nodes {

namespace {

std::string frameName(const std::string& name, const std::string& what, const std::string& origin) {
  const std::string bare(canonicalFrameName(name));
  if (bare.empty()) throw CommandLineError(origin + ": " + what + " is missing or empty");
  const std::string why = whyUnsendable(bare);
  if (!why.empty()) throw CommandLineError(origin + ": " + what + " " + why);
  return bare;
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

Eigen::Quaterniond unitQuaternion(const Eigen::Vector4d& xyzw, const std::string& origin) {
  const double norm = xyzw.norm();
  if (std::abs(norm - 1.0) > kQuaternionNormTolerance) {
    char norm_text[32];
    std::snprintf(norm_text, sizeof norm_text, "%.6f", norm);
    throw CommandLineError(origin + ": the quaternion (qx qy qz qw) = (" + formatNumber(xyzw.x()) +
                           " " + formatNumber(xyzw.y()) + " " + formatNumber(xyzw.z()) + " " +
                           formatNumber(xyzw.w()) + ") has norm " + norm_text +
                           "; a rotation needs norm 1 (within 0.001)");
  }
  return Eigen::Quaterniond(xyzw.w(), xyzw.x(), xyzw.y(), xyzw.z()).normalized();
}

using ParentOf = std::map<std::string, std::pair<std::string, const StaticTransformSpec*>>;

/// Refuses a chain of parents that comes back to where it began, naming every link of it.
void refuseLoops(const ParentOf& parent_of) {
  enum class Walk { kOnPath, kDone };
  std::map<std::string, Walk> walked;
  for (const auto& start : parent_of) {
    std::vector<std::string> path;
    std::string frame = start.first;
    while (parent_of.count(frame) != 0 && walked.count(frame) == 0) {
      walked[frame] = Walk::kOnPath;
      path.push_back(frame);
      frame = parent_of.at(frame).first;
    }
    const auto again = walked.find(frame);
    if (again != walked.end() && again->second == Walk::kOnPath) {
      const auto first = std::find(path.begin(), path.end(), frame);
      std::string chain = "'" + frame + "'";
      std::string origins;
      for (auto link = path.end(); link != first;) {
        --link;
        chain += " -> '" + *link + "'";
        origins += (origins.empty() ? "" : ", ") + parent_of.at(*link).second->origin;
      }
      throw CommandLineError("the transforms make a loop, " + chain + " (given at " + origins +
                             "); frames must form a tree");
    }
    for (const std::string& done : path) walked[done] = Walk::kDone;
  }
}

}  // namespace

TransformStamped toStaticTransform(const StaticTransformSpec& spec, TimePoint stamp) {
  TransformStamped transform;
  transform.stamp = stamp;
  transform.parent_frame = frameName(spec.frame_id, "the parent frame (frame_id)", spec.origin);
  transform.child_frame =
      frameName(spec.child_frame_id, "the child frame (child_frame_id)", spec.origin);
  if (transform.parent_frame == transform.child_frame) {
    throw CommandLineError(spec.origin + ": frame '" + transform.child_frame +
                           "' cannot be its own parent");
  }
  if (!spec.translation.allFinite()) {
    throw CommandLineError(spec.origin + ": the translation is not finite");
  }
  if (spec.quaternion_xyzw && spec.roll_pitch_yaw) {
    throw CommandLineError(spec.origin +
                           ": give the rotation either as a quaternion (qx qy qz qw) or as "
                           "roll/pitch/yaw, not both");
  }
  transform.transform.translation = spec.translation;
  if (spec.quaternion_xyzw) {
    transform.transform.rotation = unitQuaternion(*spec.quaternion_xyzw, spec.origin);
  } else if (spec.roll_pitch_yaw) {
    transform.transform.rotation = toQuaternion(*spec.roll_pitch_yaw);
  }
  return transform;
}

std::vector<TransformStamped> toStaticTransforms(const std::vector<StaticTransformSpec>& specs,
                                                 TimePoint stamp) {
  std::vector<TransformStamped> transforms;
  ParentOf parent_of;
  for (const StaticTransformSpec& spec : specs) {
    const TransformStamped& transform = transforms.emplace_back(toStaticTransform(spec, stamp));
    const auto [seen, inserted] =
        parent_of.try_emplace(transform.child_frame, transform.parent_frame, &spec);
    if (!inserted) {
      throw CommandLineError(spec.origin + ": frame '" + seen->first +
                             "' already has a parent, given at " + seen->second.second->origin +
                             "; a frame has one parent");
    }
  }
  refuseLoops(parent_of);
  return transforms;
}

}  // namespace lcmtf::nodes
