#include "lcmtf/nodes/pose_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "lcmtf/nodes/program_support.hpp"

namespace lcmtf::nodes {

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

std::string bracketed(const std::vector<double>& values, int precision, std::size_t width = 0) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::string number = fixedDecimals(values[i], precision);
    if (number.size() < width) number.insert(0, width - number.size(), ' ');
    text += (i ? ", " : "") + number;
  }
  return text + "]";
}

}  // namespace

std::string fixedDecimals(double value, int precision) {
  if (std::abs(value) < 0.5 * std::pow(10.0, -precision)) value = 0.0;
  char text[400];
  std::snprintf(text, sizeof text, "%.*f", precision, value);
  return text;
}

std::string formatPose(const TransformStamped& parent_T_child, TimePoint now, int precision) {
  const Eigen::Vector3d& t = parent_T_child.transform.translation;
  const Eigen::Quaterniond q = parent_T_child.transform.rotation.normalized();
  const RollPitchYaw rpy = toRollPitchYaw(q);
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
  matrix.topLeftCorner<3, 3>() = q.toRotationMatrix();
  matrix.topRightCorner<3, 1>() = t;

  std::ostringstream text;
  if (parent_T_child.stamp == kLatestTime) {
    text << "At " << toString(now) << ", static (every edge between them is static)";
  } else {
    text << "At " << toString(parent_T_child.stamp) << " (age "
         << toString(Duration(now - parent_T_child.stamp)) << ")";
  }
  text << ": '" << parent_T_child.child_frame << "' in '" << parent_T_child.parent_frame << "'\n";
  const std::string indent = "                     ";
  text << "  translation (m)    " << bracketed({t.x(), t.y(), t.z()}, precision) << '\n'
       << "  quaternion xyzw    " << bracketed({q.x(), q.y(), q.z(), q.w()}, precision) << '\n'
       << "  roll pitch yaw     " << bracketed({rpy.roll, rpy.pitch, rpy.yaw}, precision)
       << " rad\n"
       << indent
       << bracketed({rpy.roll * kDegreesPerRadian, rpy.pitch * kDegreesPerRadian,
                     rpy.yaw * kDegreesPerRadian},
                    precision)
       << " deg\n";
  std::size_t width = 0;
  for (int i = 0; i < 16; ++i) width = std::max(width, fixedDecimals(matrix(i), precision).size());
  for (int row = 0; row < 4; ++row) {
    text << (row == 0 ? "  matrix             " : indent)
         << bracketed({matrix(row, 0), matrix(row, 1), matrix(row, 2), matrix(row, 3)}, precision,
                      width)
         << '\n';
  }
  return text.str();
}

}  // namespace lcmtf::nodes
