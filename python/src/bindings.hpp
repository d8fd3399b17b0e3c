#pragma once

// The parts of the _lcmtf module, each defined in the file of its name.

#include <pybind11/pybind11.h>

namespace lcmtf::python {

namespace py = pybind11;

void bindExceptions(py::module_& module);
void bindTime(py::module_& module);
void bindTransformStamped(py::module_& module);
void bindStatistics(py::module_& module);
void bindBuffer(py::module_& module);
void bindListener(py::module_& module);
void bindBroadcasters(py::module_& module);

}  // namespace lcmtf::python
