#include "lcmtf/time.hpp"

#include "arguments.hpp"
#include "bindings.hpp"

namespace lcmtf::python {

void bindTime(py::module_& module) {
  module.def(
      "from_utime", [](std::int64_t utime) { return seconds(fromUtime(utime)); }, py::arg("utime"),
      "Seconds since the epoch (a float, as Python keeps time) from LCM's integer microseconds.");
  module.def(
      "to_utime", [](FloatArg time) { return toUtime(timePoint(time, "time")); }, py::arg("time"),
      "LCM's integer microseconds since the epoch from seconds, rounded to the nearest "
      "microsecond.");
  module.def(
      "_check_timeout", [](FloatArg timeout) { duration(timeout, "timeout"); }, py::arg("timeout"),
      "Raises what a lookup would for this timeout; for lcmtf's own use.");
}

}  // namespace lcmtf::python
