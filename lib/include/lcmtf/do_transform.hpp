#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lcmtf/exceptions.hpp"
#include "lcmtf/frame_name.hpp"
#include "lcmtf/geometry_types.hpp"
#include "lcmtf/stamped.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf {

/// `target_T_source` applied to data given in the source frame; the result is in the target.
/// Points and clouds are rotated and translated; directions and orientations only rotated.
/// Every form rotates by the same rotationMatrix(): NaN and infinite inputs come out alike in
/// each, coordinate by coordinate, as tf2's do.
Eigen::Vector3d transformed(const Transform& target_T_source, const Eigen::Vector3d& point);
Direction transformed(const Transform& target_T_source, const Direction& direction);
Eigen::Quaterniond transformed(const Transform& target_T_source,
                               const Eigen::Quaterniond& rotation);
Transform transformed(const Transform& target_T_source, const Transform& pose);
Eigen::Isometry3d transformed(const Transform& target_T_source, const Eigen::Isometry3d& pose);
/// Every column is a point; one matrix product for the whole cloud.
Eigen::Matrix3Xd transformed(const Transform& target_T_source, const Eigen::Matrix3Xd& cloud);
/// The same into `result` (3 x N, not overlapping `cloud`; std::invalid_argument for another
/// N), for clouds in memory the caller owns (a mapped buffer, a numpy array), with no copy.
void transformCloud(const Transform& target_T_source,
                    const Eigen::Ref<const Eigen::Matrix3Xd>& cloud,
                    Eigen::Ref<Eigen::Matrix3Xd> result);
std::vector<Eigen::Vector3d> transformed(const Transform& target_T_source,
                                         const std::vector<Eigen::Vector3d>& cloud);
/// Angular part rotated; linear part rotated plus the lever arm p x (R w), so the result is
/// the velocity of the body point at the target frame's origin.
Twist transformed(const Transform& target_T_source, const Twist& twist);
/// Force rotated; torque rotated plus p x (R f), so it is taken about the target's origin.
Wrench transformed(const Transform& target_T_source, const Wrench& wrench);
/// Pose composed; covariance rotated into the target frame: J S J^T with J = diag(R, R),
/// block by block, so an infinite variance in one 3x3 block leaves the other blocks finite.
PoseWithCovariance transformed(const Transform& target_T_source, const PoseWithCovariance& pose);

/// Transforms stamped data with a transform from lookupTransform(target, data's frame, ...):
/// the output carries the transform's parent frame and stamp. Throws
/// InvalidArgumentException when the data is not in the transform's child frame.
template <class T>
void doTransform(const Stamped<T>& in, Stamped<T>& out, const TransformStamped& transform) {
  if (canonicalFrameName(in.frame_id) != canonicalFrameName(transform.child_frame)) {
    throw InvalidArgumentException("doTransform: data in frame '" + in.frame_id +
                                   "' given a transform from frame '" + transform.child_frame +
                                   "' (into '" + transform.parent_frame + "')");
  }
  out.data = transformed(transform.transform, in.data);
  out.frame_id = transform.parent_frame;
  out.stamp = transform.stamp;
}

/// The same, returning the result.
template <class T>
Stamped<T> doTransform(const Stamped<T>& in, const TransformStamped& transform) {
  Stamped<T> out;
  doTransform(in, out, transform);
  return out;
}

}  // namespace lcmtf
