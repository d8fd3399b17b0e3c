#pragma once

// A Python callable called from a C++ thread.

#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <string>

namespace lcmtf::python {

namespace py = pybind11;

/// Calls `callable(message)` with the GIL taken, from whichever thread calls it; an exception
/// it raises is printed as unraisable (it has no caller to go to).
inline std::function<void(const std::string&)> messageCallback(py::object callable,
                                                               const char* context) {
  auto held = std::shared_ptr<py::object>(new py::object(std::move(callable)), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
  return [held, context](const std::string& message) {
    py::gil_scoped_acquire gil;
    try {
      (*held)(message);
    } catch (py::error_already_set& error) {
      error.discard_as_unraisable(context);
    }
  };
}

/// messageCallback for an optional callable argument: empty when it is None, TypeError naming
/// `argument` when it is not callable.
inline std::function<void(const std::string&)> optionalMessageCallback(py::handle value,
                                                                       const char* argument,
                                                                       const char* context) {
  if (value.is_none()) return {};
  if (!PyCallable_Check(value.ptr())) {
    throw py::type_error(std::string(argument) + " must be callable or None, not " +
                         Py_TYPE(value.ptr())->tp_name);
  }
  return messageCallback(py::reinterpret_borrow<py::object>(value), context);
}

}  // namespace lcmtf::python
