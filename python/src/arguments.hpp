#pragma once

// Arguments from Python, checked one by one so that a wrong type or value raises TypeError or
// ValueError naming the argument, before anything reaches the library.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "lcmtf/time.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf::python {

namespace py = pybind11;

/// A parameter taken as it comes and checked in the function body by one of the functions
/// below; Expected only names the type signatures show.
template <class Expected>
struct Unchecked {
  py::handle value;
};
struct StrType {
  static constexpr auto name = py::detail::const_name("str");
};
struct FloatType {
  static constexpr auto name = py::detail::const_name("float");
};
struct ArrayType {
  static constexpr auto name = py::detail::const_name("numpy.ndarray");
};
struct IntType {
  static constexpr auto name = py::detail::const_name("int");
};
struct OptionalStrType {
  static constexpr auto name = py::detail::const_name("Optional[str]");
};
using StrArg = Unchecked<StrType>;
using FloatArg = Unchecked<FloatType>;
using ArrayArg = Unchecked<ArrayType>;
using IntArg = Unchecked<IntType>;
using OptionalStrArg = Unchecked<OptionalStrType>;

/// A str, or TypeError naming `argument`.
std::string text(StrArg value, const char* argument);
/// A str, or `fallback` for None.
std::string textOr(OptionalStrArg value, const char* argument, const std::string& fallback);
/// The same, or ValueError naming `argument` when the name cannot be sent (whyUnsendable()).
std::string sendableTextOr(OptionalStrArg value, const char* argument, const std::string& fallback);
/// Every element a str; None gives none.
std::vector<std::string> textList(py::handle value, const char* argument);
/// An int from `least` to `most` (not a bool), or TypeError or ValueError naming `argument`.
std::size_t count(IntArg value, const char* argument, std::size_t least,
                  std::size_t most = std::size_t{1} << 62);
/// A float (an int or numpy scalar too; not a bool or a str), or TypeError naming `argument`.
double number(FloatArg value, const char* argument);
/// Seconds since the epoch, 0.0 for the latest; ValueError for NaN, infinity or before 1970.
TimePoint timePoint(FloatArg value, const char* argument);
/// A number of seconds from 0 to 1e9.
Duration duration(FloatArg value, const char* argument);
/// A sequence or array of `size` finite real numbers.
Eigen::VectorXd finiteVector(py::handle value, Eigen::Index size, const char* argument);
/// An (x, y, z, w) quaternion of finite numbers, not all zero.
Eigen::Quaterniond quaternion(py::handle value, const char* argument);
/// A TransformStamped, or TypeError naming `argument`.
const TransformStamped& transformStamped(py::handle value, const std::string& argument);
/// Every element a TransformStamped (TypeError naming `argument[i]` otherwise).
std::vector<TransformStamped> transformStampedList(py::handle value, const char* argument);
/// An (N, 3) array of real numbers as float64 in C order: the array itself when it already is
/// one, a converted copy otherwise.
py::array_t<double> pointArray(ArrayArg value, const char* argument);

/// Seconds as Python keeps time: the double nearest to the microseconds given.
double seconds(Duration length);
double seconds(TimePoint time);

}  // namespace lcmtf::python

namespace pybind11::detail {

template <class Expected>
struct type_caster<lcmtf::python::Unchecked<Expected>> {
  PYBIND11_TYPE_CASTER(lcmtf::python::Unchecked<Expected>, Expected::name);
  bool load(handle source, bool) {
    value.value = source;
    return true;
  }
};

}  // namespace pybind11::detail
