#pragma once

// The Buffer class, defined over three files: inserts and introspection, lookups, clouds.

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "lcmtf/buffer.hpp"

namespace lcmtf::python {

namespace py = pybind11;

/// Shared, so that a wait abandoned by Ctrl-C keeps its buffer until it ends.
using BufferPtr = std::shared_ptr<Buffer>;
using BufferClass = py::class_<Buffer, BufferPtr>;

void defineLookups(BufferClass& buffer_class);
void definePointClouds(BufferClass& buffer_class);

/// target_T_source at `time`, waiting up to `timeout` for it as Buffer::lookupTransform does.
TransformStamped lookup(const BufferPtr& buffer, const std::string& target,
                        const std::string& source, TimePoint time, Duration timeout);
/// The same by time travel through `fixed`.
TransformStamped lookup(const BufferPtr& buffer, const std::string& target, TimePoint target_time,
                        const std::string& source, TimePoint source_time, const std::string& fixed,
                        Duration timeout);

}  // namespace lcmtf::python
