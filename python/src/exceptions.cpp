#include "lcmtf/exceptions.hpp"

#include "bindings.hpp"

namespace lcmtf::python {

namespace {

// The Python class for the C++ exception `Cpp`, under `base`, raised with the C++ message.
template <class Cpp>
py::handle define(py::module_& module, const char* name, py::handle base, const char* doc) {
  py::exception<Cpp>& python_class = py::register_exception<Cpp>(module, name, base);
  python_class.attr("__doc__") = doc;
  python_class.attr("__module__") = "lcmtf";
  return python_class;
}

}  // namespace

void bindExceptions(py::module_& module) {
  // Bases first: a C++ exception is translated by the last registered class that catches it.
  const py::handle transform = define<TransformException>(
      module, "TransformException", PyExc_RuntimeError,
      "Base of every error a lookup or transform raises; the message names the frames and "
      "times.");
  define<LookupException>(module, "LookupException", transform,
                          "A frame the buffer has never heard of, or a loop in the tree.");
  define<ConnectivityException>(module, "ConnectivityException", transform,
                                "Two frames with no common ancestor at the time asked.");
  const py::handle extrapolation =
      define<ExtrapolationException>(module, "ExtrapolationException", transform,
                                     "The time asked lies outside the history of an edge on the "
                                     "path.");
  define<PastExtrapolationException>(module, "PastExtrapolationException", extrapolation,
                                     "The time asked is older than an edge's oldest sample.");
  define<FutureExtrapolationException>(module, "FutureExtrapolationException", extrapolation,
                                       "The time asked is newer than an edge's newest sample.");
  define<InterpolationGapException>(
      module, "InterpolationGapException", extrapolation,
      "The time asked falls between two samples of an edge further apart than the buffer's "
      "max_interpolation_gap.");
  define<InvalidArgumentException>(module, "InvalidArgumentException", transform,
                                   "An argument that can never be valid, such as an empty frame "
                                   "name.");
  define<TimeoutException>(module, "TimeoutException", transform,
                           "Waiting for a transform ran out of time.");
}

}  // namespace lcmtf::python
