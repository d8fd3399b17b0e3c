#include "bindings.hpp"
#include "closes_at_exit.hpp"
#include "released_wait.hpp"

PYBIND11_MODULE(_lcmtf, module) {
  module.doc() = "The compiled part of the lcmtf package; import lcmtf instead.";
  lcmtf::python::rememberMainThread();
  lcmtf::python::closeEverythingAtExit();
  lcmtf::python::bindExceptions(module);
  lcmtf::python::bindTime(module);
  lcmtf::python::bindTransformStamped(module);
  lcmtf::python::bindStatistics(module);
  lcmtf::python::bindBuffer(module);
  lcmtf::python::bindListener(module);
  lcmtf::python::bindBroadcasters(module);
}
