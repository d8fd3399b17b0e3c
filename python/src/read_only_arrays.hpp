#pragma once

// Results handed to Python as numpy arrays of their own that cannot be written to, so that
// `t.translation[0] = 1` fails loudly instead of changing a copy nobody sees.

#include <pybind11/numpy.h>

#include <Eigen/Core>

namespace lcmtf::python {

namespace py = pybind11;

/// A read-only float64 array of `rows` x `cols` (one dimension when cols is 0), copied from
/// `values` in row-major order.
inline py::array_t<double> readOnlyArray(const double* values, py::ssize_t rows,
                                         py::ssize_t cols = 0) {
  py::array_t<double> array =
      cols == 0 ? py::array_t<double>(rows) : py::array_t<double>({rows, cols});
  std::copy(values, values + rows * (cols == 0 ? 1 : cols), array.mutable_data());
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

inline py::array_t<double> readOnlyArray(const Eigen::Vector3d& vector) {
  return readOnlyArray(vector.data(), 3);
}

}  // namespace lcmtf::python
