#include "lcmtf/message_conversions.hpp"

namespace lcmtf {

vector3_t toMessage(const Eigen::Vector3d& vector) {
  vector3_t message{};
  message.x = vector.x();
  message.y = vector.y();
  message.z = vector.z();
  return message;
}

quaternion_t toMessage(const Eigen::Quaterniond& rotation) {
  quaternion_t message{};
  message.x = rotation.x();
  message.y = rotation.y();
  message.z = rotation.z();
  message.w = rotation.w();
  return message;
}

transform_t toMessage(const TransformStamped& transform) {
  transform_t message{};
  message.utime = toUtime(transform.stamp);
  message.parent_frame = transform.parent_frame;
  message.child_frame = transform.child_frame;
  message.translation = toMessage(transform.transform.translation);
  message.rotation = toMessage(transform.transform.rotation);
  return message;
}

Eigen::Vector3d fromMessage(const vector3_t& vector) {
  return Eigen::Vector3d(vector.x, vector.y, vector.z);
}

Eigen::Quaterniond fromMessage(const quaternion_t& rotation) {
  return Eigen::Quaterniond(rotation.w, rotation.x, rotation.y, rotation.z);
}

TransformStamped fromMessage(const transform_t& transform) {
  TransformStamped out;
  fromMessage(transform, out);
  return out;
}

void fromMessage(const transform_t& transform, TransformStamped& out) {
  out.stamp = fromUtime(transform.utime);
  out.parent_frame.assign(transform.parent_frame);
  out.child_frame.assign(transform.child_frame);
  out.transform = Transform(fromMessage(transform.translation), fromMessage(transform.rotation));
}

Eigen::Isometry3d toIsometry(const TransformStamped& transform) {
  return transform.transform.toIsometry();
}

Eigen::Isometry3d toIsometry(const transform_t& transform) {
  return toIsometry(fromMessage(transform));
}

TransformStamped toTransformStamped(const Eigen::Isometry3d& parent_T_child, TimePoint stamp,
                                    std::string parent_frame, std::string child_frame) {
  return TransformStamped{stamp, std::move(parent_frame), std::move(child_frame),
                          Transform::fromIsometry(parent_T_child)};
}

transform_t toMessage(const Eigen::Isometry3d& parent_T_child, TimePoint stamp,
                      std::string parent_frame, std::string child_frame) {
  return toMessage(
      toTransformStamped(parent_T_child, stamp, std::move(parent_frame), std::move(child_frame)));
}

}  // namespace lcmtf
