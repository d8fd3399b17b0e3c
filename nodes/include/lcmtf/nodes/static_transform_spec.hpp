#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lcmtf/nodes/program_support.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf::nodes {

/// A static transform as a person writes it: values left out are zero, a rotation left out is
/// the identity. `origin` says where it was given ("--file robot.yaml, transform 2").
struct StaticTransformSpec {
  std::string frame_id;
  std::string child_frame_id;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector4d> quaternion_xyzw;
  std::optional<RollPitchYaw> roll_pitch_yaw;
  std::string origin;
};

/// How far from 1 a quaternion's norm may be; within it the quaternion is normalized.
inline constexpr double kQuaternionNormTolerance = 1e-3;

/// frame_id_T_child_frame_id at `stamp`. CommandLineError, naming the origin, for an empty or
/// repeated frame name, both rotation forms at once, or a quaternion whose norm is not 1.
TransformStamped toStaticTransform(const StaticTransformSpec& spec, TimePoint stamp);

/// All of them at `stamp`; CommandLineError when two give the same child frame.
std::vector<TransformStamped> toStaticTransforms(const std::vector<StaticTransformSpec>& specs,
                                                 TimePoint stamp);

}  // namespace lcmtf::nodes
