#include "lcmtf/do_transform.hpp"

#include "arguments.hpp"
#include "buffer_class.hpp"
#include "without_gil.hpp"

namespace lcmtf::python {

namespace {

// The cloud moved by target_T_source into a new (N, 3) array; the GIL is released while the
// points are read and written.
py::array_t<double> moved(const py::array_t<double>& points, const Transform& target_T_source) {
  const py::ssize_t count = points.shape(0);
  py::array_t<double> result({count, py::ssize_t{3}});
  const Eigen::Index columns = static_cast<Eigen::Index>(count);
  const Eigen::Map<const Eigen::Matrix3Xd> cloud(points.data(), 3, columns);
  Eigen::Map<Eigen::Matrix3Xd> into(result.mutable_data(), 3, columns);
  withoutGil([&] { transformCloud(target_T_source, cloud, into); });
  return result;
}

}  // namespace

void definePointClouds(BufferClass& buffer_class) {
  buffer_class.def(
      "transform_points",
      [](const BufferPtr& buffer, ArrayArg points, StrArg source_frame, StrArg target_frame,
         FloatArg time, FloatArg timeout) {
        const py::array_t<double> cloud = pointArray(points, "points");
        const TransformStamped target_T_source =
            lookup(buffer, text(target_frame, "target_frame"), text(source_frame, "source_frame"),
                   timePoint(time, "time"), duration(timeout, "timeout"));
        return moved(cloud, target_T_source.transform);
      },
      py::arg("points"), py::arg("source_frame"), py::arg("target_frame"), py::arg("time") = 0.0,
      py::arg("timeout") = 0.0,
      "Points given in source_frame at `time` (an (N, 3) array of x, y, z rows), expressed "
      "in target_frame: a new (N, 3) float64 array, in one call for the whole cloud. NaN and "
      "infinite coordinates pass through as the arithmetic makes them. The lookup waits up to "
      "`timeout` seconds and raises what lookup_transform raises. The second form is time "
      "travel: the points as seen at source_time, through fixed_frame, into target_frame as "
      "it was at target_time.");
  buffer_class.def(
      "transform_points",
      [](const BufferPtr& buffer, ArrayArg points, StrArg source_frame, FloatArg source_time,
         StrArg target_frame, FloatArg target_time, StrArg fixed_frame, FloatArg timeout) {
        const py::array_t<double> cloud = pointArray(points, "points");
        const TransformStamped target_T_source = lookup(
            buffer, text(target_frame, "target_frame"), timePoint(target_time, "target_time"),
            text(source_frame, "source_frame"), timePoint(source_time, "source_time"),
            text(fixed_frame, "fixed_frame"), duration(timeout, "timeout"));
        return moved(cloud, target_T_source.transform);
      },
      py::arg("points"), py::arg("source_frame"), py::arg("source_time"), py::arg("target_frame"),
      py::arg("target_time"), py::arg("fixed_frame"), py::arg("timeout") = 0.0);
}

}  // namespace lcmtf::python
