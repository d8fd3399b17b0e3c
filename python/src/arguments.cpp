#include "arguments.hpp"

#include <cmath>

#include "lcmtf/sendable_names.hpp"

namespace lcmtf::python {

namespace {

// The largest number of seconds whose microseconds fit in a TimePoint.
constexpr double kMostSeconds = 9.2e12;
// The longest duration taken, about 31 years: a deadline that far on a clock counting
// nanoseconds still fits in 64 bits.
constexpr double kMostDurationSeconds = 1e9;

std::string typeName(py::handle value) { return Py_TYPE(value.ptr())->tp_name; }

std::string shapeText(const py::array& array) { return py::str(array.attr("shape")); }

// numpy's own conversion of `value`, or TypeError saying what `argument` must be.
py::array numericArray(py::handle value, const std::string& argument, const char* expected) {
  py::array array = py::array::ensure(value);
  if (!array) {
    throw py::type_error(argument + " must be " + expected + ", not " + typeName(value));
  }
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f') {
    throw py::type_error(argument + " must hold real numbers, not " +
                         std::string(py::str(array.dtype())) + " values");
  }
  return array;
}

}  // namespace

std::string text(StrArg value, const char* argument) {
  if (!PyUnicode_Check(value.value.ptr())) {
    throw py::type_error(std::string(argument) + " must be a str, not " + typeName(value.value));
  }
  Py_ssize_t size = 0;
  const char* utf8 = PyUnicode_AsUTF8AndSize(value.value.ptr(), &size);
  if (utf8 == nullptr) throw py::error_already_set();
  std::string result(utf8, static_cast<std::size_t>(size));
  // LCM carries and C reads names only up to their first NUL: it would cut such a name short.
  if (result.find('\0') != std::string::npos) {
    throw py::value_error(std::string(argument) + " must not contain a NUL character ('\\x00')");
  }
  return result;
}

std::string textOr(OptionalStrArg value, const char* argument, const std::string& fallback) {
  if (value.value.is_none()) return fallback;
  return text(StrArg{value.value}, argument);
}

std::string sendableTextOr(OptionalStrArg value, const char* argument,
                           const std::string& fallback) {
  std::string name = textOr(value, argument, fallback);
  const std::string why = whyUnsendable(name);
  if (!why.empty()) throw py::value_error(std::string(argument) + " " + why);
  return name;
}

std::vector<std::string> textList(py::handle value, const char* argument) {
  std::vector<std::string> result;
  if (value.is_none()) return result;
  if (!py::isinstance<py::iterable>(value) || PyUnicode_Check(value.ptr())) {
    throw py::type_error(std::string(argument) + " must be an iterable of str, not " +
                         typeName(value));
  }
  for (py::handle item : value) {
    const std::string element = std::string(argument) + "[" + std::to_string(result.size()) + "]";
    result.push_back(text(StrArg{item}, element.c_str()));
  }
  return result;
}

std::size_t count(IntArg value, const char* argument, std::size_t least, std::size_t most) {
  PyObject* object = value.value.ptr();
  if (!PyLong_Check(object) || PyBool_Check(object)) {
    throw py::type_error(std::string(argument) + " must be an int, not " + typeName(value.value));
  }
  const long long result = PyLong_AsLongLong(object);
  if (result == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (result < static_cast<long long>(least) || result > static_cast<long long>(most)) {
    throw py::value_error(std::string(argument) + " must be from " + std::to_string(least) +
                          " to " + std::to_string(most) + ", not " + std::to_string(result));
  }
  return static_cast<std::size_t>(result);
}

double number(FloatArg value, const char* argument) {
  PyObject* object = value.value.ptr();
  if (PyFloat_CheckExact(object)) return PyFloat_AS_DOUBLE(object);
  if (!PyBool_Check(object) && !PyUnicode_Check(object) && !PyBytes_Check(object)) {
    const double result = PyFloat_AsDouble(object);
    if (result != -1.0 || !PyErr_Occurred()) return result;
    if (PyErr_ExceptionMatches(PyExc_OverflowError)) throw py::error_already_set();
    PyErr_Clear();
  }
  throw py::type_error(std::string(argument) + " must be a float, not " + typeName(value.value));
}

TimePoint timePoint(FloatArg value, const char* argument) {
  const double time = number(value, argument);
  if (!(time >= 0.0 && time <= kMostSeconds)) {
    throw py::value_error(std::string(argument) +
                          " must be seconds since the epoch from 0 to 9.2e12 (0.0 for the latest); "
                          "got " +
                          std::string(py::repr(py::float_(time))));
  }
  return fromSeconds(time);
}

Duration duration(FloatArg value, const char* argument) {
  const double length = number(value, argument);
  if (!(length >= 0.0 && length <= kMostDurationSeconds)) {
    throw py::value_error(std::string(argument) +
                          " must be a number of seconds from 0 to 1e9; got " +
                          std::string(py::repr(py::float_(length))));
  }
  return secondsToDuration(length);
}

Eigen::VectorXd finiteVector(py::handle value, Eigen::Index size, const char* argument) {
  Eigen::VectorXd result(size);
  if (PyList_Check(value.ptr()) || PyTuple_Check(value.ptr())) {
    const py::sequence items = py::reinterpret_borrow<py::sequence>(value);
    if (static_cast<Eigen::Index>(items.size()) != size) {
      throw py::value_error(std::string(argument) + " must have " + std::to_string(size) +
                            " elements, not " + std::to_string(items.size()));
    }
    for (Eigen::Index i = 0; i < size; ++i) {
      const std::string element = std::string(argument) + "[" + std::to_string(i) + "]";
      result[i] = number(FloatArg{items[static_cast<std::size_t>(i)]}, element.c_str());
    }
  } else {
    const std::string expected = "a sequence of " + std::to_string(size) + " numbers";
    const py::array array = numericArray(value, argument, expected.c_str());
    if (array.ndim() != 1 || array.shape(0) != size) {
      throw py::value_error(std::string(argument) + " must have shape (" + std::to_string(size) +
                            ",), not " + shapeText(array));
    }
    const auto values = py::array_t<double, py::array::forcecast>::ensure(array);
    for (Eigen::Index i = 0; i < size; ++i) result[i] = values.at(i);
  }
  if (!result.allFinite()) {
    throw py::value_error(std::string(argument) + " must be finite, not " +
                          std::string(py::repr(value)));
  }
  return result;
}

Eigen::Quaterniond quaternion(py::handle value, const char* argument) {
  const Eigen::VectorXd xyzw = finiteVector(value, 4, argument);
  if (xyzw.squaredNorm() == 0.0) {
    throw py::value_error(std::string(argument) +
                          " must be a quaternion (x, y, z, w) of "
                          "non-zero length, not all zeros");
  }
  return Eigen::Quaterniond(xyzw[3], xyzw[0], xyzw[1], xyzw[2]);
}

const TransformStamped& transformStamped(py::handle value, const std::string& argument) {
  if (!py::isinstance<TransformStamped>(value)) {
    throw py::type_error(argument + " must be a TransformStamped, not " + typeName(value));
  }
  return value.cast<const TransformStamped&>();
}

std::vector<TransformStamped> transformStampedList(py::handle value, const char* argument) {
  if (!py::isinstance<py::iterable>(value) || PyUnicode_Check(value.ptr())) {
    throw py::type_error(std::string(argument) + " must be an iterable of TransformStamped, not " +
                         typeName(value));
  }
  std::vector<TransformStamped> result;
  for (py::handle item : value) {
    result.push_back(
        transformStamped(item, std::string(argument) + "[" + std::to_string(result.size()) + "]"));
  }
  return result;
}

py::array_t<double> pointArray(ArrayArg value, const char* argument) {
  const py::array array = numericArray(value.value, argument, "an (N, 3) array of numbers");
  if (array.ndim() != 2 || array.shape(1) != 3) {
    throw py::value_error(std::string(argument) + " must have shape (N, 3), not " +
                          shapeText(array));
  }
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
}

double seconds(Duration length) { return static_cast<double>(length.count()) / 1e6; }

double seconds(TimePoint time) { return seconds(time.time_since_epoch()); }

}  // namespace lcmtf::python
