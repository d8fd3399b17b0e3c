#include "lcmtf/transform_stamped.hpp"

#include <sstream>

#include "arguments.hpp"
#include "bindings.hpp"
#include "lcmtf/velocity.hpp"
#include "read_only_arrays.hpp"

namespace lcmtf::python {

namespace {

std::string numbers(const double* values, int count) {
  std::ostringstream text;
  text.precision(17);
  text << '[';
  for (int i = 0; i < count; ++i) text << (i == 0 ? "" : ", ") << values[i];
  text << ']';
  return text.str();
}

std::string repr(const TransformStamped& t) {
  const Eigen::Vector4d xyzw = t.transform.rotation.coeffs();
  return "TransformStamped(parent_frame=" + std::string(py::repr(py::str(t.parent_frame))) +
         ", child_frame=" + std::string(py::repr(py::str(t.child_frame))) +
         ", stamp=" + toString(t.stamp) +
         ", translation=" + numbers(t.transform.translation.data(), 3) +
         ", rotation=" + numbers(xyzw.data(), 4) + ")";
}

py::array_t<double> matrix(const Transform& transform) {
  Eigen::Matrix<double, 4, 4, Eigen::RowMajor> result = Eigen::Matrix4d::Identity();
  result.topLeftCorner<3, 3>() = transform.rotationMatrix();
  result.topRightCorner<3, 1>() = transform.translation;
  return readOnlyArray(result.data(), 4, 4);
}

bool sameFields(const TransformStamped& a, const TransformStamped& b) {
  return a.stamp == b.stamp && a.parent_frame == b.parent_frame && a.child_frame == b.child_frame &&
         a.transform.translation == b.transform.translation &&
         a.transform.rotation.coeffs() == b.transform.rotation.coeffs();
}

// The stamp as its integer microseconds, so that a round trip keeps it exactly.
py::tuple pickledState(const TransformStamped& t) {
  const Eigen::Vector3d& xyz = t.transform.translation;
  const Eigen::Vector4d xyzw = t.transform.rotation.coeffs();
  return py::make_tuple(t.parent_frame, t.child_frame, toUtime(t.stamp),
                        py::make_tuple(xyz.x(), xyz.y(), xyz.z()),
                        py::make_tuple(xyzw.x(), xyzw.y(), xyzw.z(), xyzw.w()));
}

TransformStamped unpickled(const py::tuple& state) {
  if (state.size() != 5) throw py::value_error("not a pickled lcmtf.TransformStamped");
  const auto utime = state[2].cast<std::int64_t>();
  if (utime < 0) throw py::value_error("stamp must not be before 1970");
  const Eigen::VectorXd xyz = finiteVector(state[3], 3, "translation");
  return TransformStamped{fromUtime(utime), text(StrArg{state[0]}, "parent_frame"),
                          text(StrArg{state[1]}, "child_frame"),
                          Transform(Eigen::Vector3d(xyz), quaternion(state[4], "rotation"))};
}

void bindVelocity(py::module_& module) {
  py::class_<Velocity>(module, "Velocity",
                       "Linear (m/s) and angular (rad/s) velocity of one frame relative to "
                       "another, expressed in `frame`, averaged over an interval centred on "
                       "`stamp`, or clipped to the data available.")
      .def_property_readonly(
          "stamp", [](const Velocity& v) { return seconds(v.stamp); },
          "The time asked for (the latest common time for 0.0), in seconds since the epoch: the "
          "middle of the interval, unless the interval was clipped to the data available.")
      .def_readonly("frame", &Velocity::frame, "The frame both vectors are expressed in.")
      .def_property_readonly(
          "linear", [](const Velocity& v) { return readOnlyArray(v.linear); },
          "Linear velocity (x, y, z) in m/s, a (3,) array.")
      .def_property_readonly(
          "angular", [](const Velocity& v) { return readOnlyArray(v.angular); },
          "Angular velocity (x, y, z) in rad/s, a (3,) array.")
      .def("__repr__", [](const Velocity& v) {
        return "Velocity(frame=" + std::string(py::repr(py::str(v.frame))) +
               ", stamp=" + toString(v.stamp) + ", linear=" + numbers(v.linear.data(), 3) +
               ", angular=" + numbers(v.angular.data(), 3) + ")";
      });
}

}  // namespace

void bindTransformStamped(py::module_& module) {
  py::class_<TransformStamped>(
      module, "TransformStamped",
      "parent_frame_T_child_frame at `stamp`: the pose of child_frame in parent_frame, which "
      "maps points given in child_frame into parent_frame.")
      .def(py::init([](StrArg parent_frame, StrArg child_frame, FloatArg stamp,
                       ArrayArg translation, ArrayArg rotation) {
             const Eigen::VectorXd xyz = finiteVector(translation.value, 3, "translation");
             return TransformStamped{
                 timePoint(stamp, "stamp"), text(parent_frame, "parent_frame"),
                 text(child_frame, "child_frame"),
                 Transform(Eigen::Vector3d(xyz), quaternion(rotation.value, "rotation"))};
           }),
           py::arg("parent_frame"), py::arg("child_frame"), py::arg("stamp") = 0.0,
           py::arg("translation") = py::make_tuple(0.0, 0.0, 0.0),
           py::arg("rotation") = py::make_tuple(0.0, 0.0, 0.0, 1.0),
           "`stamp` in seconds since the epoch (0.0 for a static transform), `translation` "
           "(x, y, z) in metres, `rotation` a quaternion (x, y, z, w). ValueError for NaN, "
           "infinity or a zero quaternion; TypeError for anything not numbers or str.")
      .def_property(
          "parent_frame", [](const TransformStamped& t) { return t.parent_frame; },
          [](TransformStamped& t, StrArg frame) { t.parent_frame = text(frame, "parent_frame"); },
          "The frame the pose is expressed in (a lookup's target).")
      .def_property(
          "child_frame", [](const TransformStamped& t) { return t.child_frame; },
          [](TransformStamped& t, StrArg frame) { t.child_frame = text(frame, "child_frame"); },
          "The frame whose pose this is (a lookup's source).")
      .def_property(
          "stamp", [](const TransformStamped& t) { return seconds(t.stamp); },
          [](TransformStamped& t, FloatArg stamp) { t.stamp = timePoint(stamp, "stamp"); },
          "Seconds since the epoch, to the microsecond; 0.0 for a static transform.")
      .def_property(
          "translation",
          [](const TransformStamped& t) { return readOnlyArray(t.transform.translation); },
          [](TransformStamped& t, ArrayArg xyz) {
            t.transform.translation = finiteVector(xyz.value, 3, "translation");
          },
          "(x, y, z) in metres, a read-only (3,) array; assign a new one to change it.")
      .def_property(
          "rotation",
          [](const TransformStamped& t) {
            return readOnlyArray(t.transform.rotation.coeffs().data(), 4);
          },
          [](TransformStamped& t, ArrayArg xyzw) {
            t.transform.rotation = quaternion(xyzw.value, "rotation");
          },
          "The quaternion (x, y, z, w), a read-only (4,) array; assign a new one to change it.")
      .def(
          "matrix", [](const TransformStamped& t) { return matrix(t.transform); },
          "The 4x4 homogeneous matrix [R t; 0 1] that maps points in child_frame into "
          "parent_frame.")
      .def(
          "__eq__",
          [](const TransformStamped& t, py::handle other) -> py::object {
            if (!py::isinstance<TransformStamped>(other))
              return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            return py::bool_(sameFields(t, other.cast<const TransformStamped&>()));
          },
          py::is_operator(), py::arg("other"),
          "Equal when frames, stamp, translation and quaternion are all exactly equal (q and -q "
          "differ).")
      .def(py::pickle(&pickledState, &unpickled))
      .def("__repr__", &repr);
  bindVelocity(module);
}

}  // namespace lcmtf::python
