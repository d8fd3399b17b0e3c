#include "lcmtf/buffer.hpp"

#include <pybind11/stl.h>

#include <optional>

#include "arguments.hpp"
#include "bindings.hpp"
#include "buffer_class.hpp"
#include "python_callback.hpp"
#include "without_gil.hpp"

namespace lcmtf::python {

namespace {

/// Every Buffer made from Python: its reporter, for the collector to see.
struct PythonBuffer : Buffer {
  using Buffer::Buffer;
  CallableCellPtr reporter;
};

CallableCell* reporterOf(Buffer& buffer) {
  return static_cast<PythonBuffer&>(buffer).reporter.get();
}

BufferPtr makeBuffer(FloatArg cache_time, py::handle reporter) {
  const Duration history = duration(cache_time, "cache_time");
  if (history == Duration::zero()) {
    throw py::value_error("cache_time must be more than 0 seconds");
  }
  auto buffer = std::make_shared<PythonBuffer>(history);
  buffer->reporter = callableArgument(reporter, "reporter");
  if (buffer->reporter) {
    buffer->setErrorReporter(messageCallback(buffer->reporter, "lcmtf buffer reporter"));
  }
  return buffer;
}

void defineInserts(BufferClass& buffer_class) {
  buffer_class.def(
      "set_transform",
      [](Buffer& buffer, py::handle transform, StrArg authority, bool is_static) {
        return buffer.setTransform(transformStamped(transform, "transform"),
                                   text(authority, "authority"), is_static);
      },
      py::arg("transform"), py::arg("authority"), py::arg("is_static") = false,
      "Stores transform (parent_frame_T_child_frame) at its stamp, or for all time when "
      "is_static. Returns False when the buffer refuses it (empty or equal frame names, a "
      "quaternion far from unit length, a stamp older than the history kept): the buffer is "
      "unchanged, statistics() counts the reason and the first of each kind goes to the "
      "buffer's reporter.");
  buffer_class.def(
      "set_transforms",
      [](Buffer& buffer, py::handle transforms, StrArg authority, bool is_static) {
        const std::vector<TransformStamped> batch = transformStampedList(transforms, "transforms");
        const std::string sender = text(authority, "authority");
        return withoutGil([&] { return buffer.setTransforms(batch, sender, is_static); });
      },
      py::arg("transforms"), py::arg("authority"), py::arg("is_static") = false,
      "set_transform for a whole batch under one lock, as when filling a buffer from a log; "
      "returns how many were stored.");
  buffer_class.def(
      "clear", [](Buffer& buffer) { buffer.clear(); },
      "Drops all dynamic history; frames, static transforms and statistics stay.");
}

void defineIntrospection(BufferClass& buffer_class) {
  buffer_class.def(
      "frames", [](const Buffer& buffer) { return buffer.getAllFrameNames(); },
      "Every frame ever seen, parents included, in the order they appeared.");
  buffer_class.def(
      "frame_exists",
      [](const Buffer& buffer, StrArg frame) { return buffer.frameExists(text(frame, "frame")); },
      py::arg("frame"), "Whether the buffer knows `frame`.");
  buffer_class.def(
      "get_parent",
      [](const Buffer& buffer, StrArg frame, FloatArg time) -> std::optional<std::string> {
        std::string parent;
        if (!buffer.getParent(text(frame, "frame"), timePoint(time, "time"), parent)) return {};
        return parent;
      },
      py::arg("frame"), py::arg("time") = 0.0,
      "The parent of `frame` at `time` (0.0: the latest), or None when it has none there.");
  buffer_class.def(
      "all_frames_as_yaml", [](const Buffer& buffer) { return buffer.allFramesAsYaml(); },
      "Per frame: parent, authority, average rate, samples held, oldest and newest stamp.");
  buffer_class.def(
      "all_frames_as_dot", [](const Buffer& buffer) { return buffer.allFramesAsDot(); },
      "The tree as a Graphviz digraph, edges labelled with authority, rate and history.");
  buffer_class.def(
      "statistics", [](const Buffer& buffer) { return buffer.statistics(); },
      "What inserts have stored and refused since the buffer was made (InsertStatistics).");
  buffer_class.def_property_readonly(
      "cache_time", [](const Buffer& buffer) { return seconds(buffer.cacheTime()); },
      "Seconds of history each dynamic edge keeps behind its newest sample.");
  buffer_class.def_property(
      "max_interpolation_gap",
      [](const Buffer& buffer) { return seconds(buffer.maxInterpolationGap()); },
      [](Buffer& buffer, FloatArg gap) {
        buffer.setMaxInterpolationGap(duration(gap, "max_interpolation_gap"));
      },
      "Seconds: a lookup between two samples of an edge further apart raises "
      "InterpolationGapException instead of interpolating. 0.0 (the default) sets no limit.");
}

}  // namespace

void bindBuffer(py::module_& module) {
  BufferClass buffer_class(
      module, "Buffer", collectableCallback<Buffer, &reporterOf>(),
      "The frame tree over time: each edge's recent history and the static edges, and lookups "
      "between any two frames at any stored time. Fill it with a TransformListener, or by "
      "hand with set_transform. Any number of threads may look up while others insert.");
  buffer_class.def(py::init(&makeBuffer), py::arg("cache_time") = 10.0, py::kw_only(),
                   py::arg("reporter") = py::none(),
                   "`cache_time`: seconds of history each dynamic edge keeps behind its newest "
                   "sample. `reporter(message)` gets the first transform refused for each reason "
                   "(None: printed on stderr), from the thread that inserted it: a listener's or "
                   "the caller's.");
  defineInserts(buffer_class);
  defineLookups(buffer_class);
  definePointClouds(buffer_class);
  defineIntrospection(buffer_class);
}

}  // namespace lcmtf::python
