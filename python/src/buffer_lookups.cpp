#include <utility>

#include "arguments.hpp"
#include "buffer_class.hpp"
#include "released_wait.hpp"

namespace lcmtf::python {

namespace {

using Verdict = std::pair<bool, std::string>;

// Answers at once when the data is there, so that only a real wait pays for one; the wait is
// then Buffer's own, with its errors and messages.
template <class Immediate, class Waiting>
TransformStamped lookupOrWait(Duration timeout, Immediate immediate, Waiting waiting) {
  if (timeout == Duration::zero()) return immediate();
  try {
    return immediate();
  } catch (const TransformException&) {
    return waitReleased<TransformStamped>(waiting);
  }
}

template <class Immediate, class Waiting>
py::object canOrWait(Duration timeout, bool return_debug_tuple, Immediate immediate,
                     Waiting waiting) {
  Verdict verdict;
  verdict.first = immediate(&verdict.second);
  if (!verdict.first && timeout > Duration::zero()) verdict = waitReleased<Verdict>(waiting);
  if (return_debug_tuple) return py::make_tuple(verdict.first, verdict.second);
  return py::bool_(verdict.first);
}

constexpr const char* kLookupDoc =
    "target_T_source: the transform that maps data in `source` into `target`, with "
    "parent_frame = target and child_frame = source. `time` 0.0 means the latest time every "
    "edge on the path has data; the result's stamp says which. With `timeout` (seconds), waits "
    "for the data with the GIL released. The second form is time travel: source at "
    "source_time into `fixed`, then `fixed` at target_time into target.\n\n"
    "Raises LookupException, ConnectivityException, ExtrapolationException, "
    "InvalidArgumentException or TimeoutException (all TransformException).";

constexpr const char* kCanDoc =
    "Whether lookup_transform with the same arguments would succeed, waiting up to `timeout` "
    "seconds for it; never raises a TransformException. With return_debug_tuple, returns "
    "(bool, reason) where reason says what is missing.";

void defineLookupTransform(BufferClass& buffer_class) {
  buffer_class.def(
      "lookup_transform",
      [](const BufferPtr& buffer, StrArg target, StrArg source, FloatArg time, FloatArg timeout) {
        return lookup(buffer, text(target, "target"), text(source, "source"),
                      timePoint(time, "time"), duration(timeout, "timeout"));
      },
      py::arg("target"), py::arg("source"), py::arg("time") = 0.0, py::arg("timeout") = 0.0,
      kLookupDoc);
  buffer_class.def(
      "lookup_transform",
      [](const BufferPtr& buffer, StrArg target, FloatArg target_time, StrArg source,
         FloatArg source_time, StrArg fixed, FloatArg timeout) {
        return lookup(buffer, text(target, "target"), timePoint(target_time, "target_time"),
                      text(source, "source"), timePoint(source_time, "source_time"),
                      text(fixed, "fixed"), duration(timeout, "timeout"));
      },
      py::arg("target"), py::arg("target_time"), py::arg("source"), py::arg("source_time"),
      py::arg("fixed"), py::arg("timeout") = 0.0);
}

void defineCanTransform(BufferClass& buffer_class) {
  buffer_class.def(
      "can_transform",
      [](const BufferPtr& buffer, StrArg target_arg, StrArg source_arg, FloatArg time_arg,
         FloatArg timeout_arg, bool return_debug_tuple) {
        const std::string target = text(target_arg, "target");
        const std::string source = text(source_arg, "source");
        const TimePoint time = timePoint(time_arg, "time");
        const Duration timeout = duration(timeout_arg, "timeout");
        return canOrWait(
            timeout, return_debug_tuple,
            [&](std::string* why) {
              return buffer->BufferCore::canTransform(target, source, time, why);
            },
            [=]() {
              Verdict verdict;
              verdict.first = buffer->canTransform(target, source, time, timeout, &verdict.second);
              return verdict;
            });
      },
      py::arg("target"), py::arg("source"), py::arg("time") = 0.0, py::arg("timeout") = 0.0,
      py::kw_only(), py::arg("return_debug_tuple") = false, kCanDoc);
  buffer_class.def(
      "can_transform",
      [](const BufferPtr& buffer, StrArg target_arg, FloatArg target_time_arg, StrArg source_arg,
         FloatArg source_time_arg, StrArg fixed_arg, FloatArg timeout_arg,
         bool return_debug_tuple) {
        const std::string target = text(target_arg, "target");
        const TimePoint target_time = timePoint(target_time_arg, "target_time");
        const std::string source = text(source_arg, "source");
        const TimePoint source_time = timePoint(source_time_arg, "source_time");
        const std::string fixed = text(fixed_arg, "fixed");
        const Duration timeout = duration(timeout_arg, "timeout");
        return canOrWait(
            timeout, return_debug_tuple,
            [&](std::string* why) {
              return buffer->BufferCore::canTransform(target, target_time, source, source_time,
                                                      fixed, why);
            },
            [=]() {
              Verdict verdict;
              verdict.first = buffer->canTransform(target, target_time, source, source_time, fixed,
                                                   timeout, &verdict.second);
              return verdict;
            });
      },
      py::arg("target"), py::arg("target_time"), py::arg("source"), py::arg("source_time"),
      py::arg("fixed"), py::arg("timeout") = 0.0, py::kw_only(),
      py::arg("return_debug_tuple") = false);
}

}  // namespace

TransformStamped lookup(const BufferPtr& buffer, const std::string& target,
                        const std::string& source, TimePoint time, Duration timeout) {
  return lookupOrWait(
      timeout, [&] { return buffer->BufferCore::lookupTransform(target, source, time); },
      [=] { return buffer->lookupTransform(target, source, time, timeout); });
}

TransformStamped lookup(const BufferPtr& buffer, const std::string& target, TimePoint target_time,
                        const std::string& source, TimePoint source_time, const std::string& fixed,
                        Duration timeout) {
  return lookupOrWait(
      timeout,
      [&] {
        return buffer->BufferCore::lookupTransform(target, target_time, source, source_time, fixed);
      },
      [=] {
        return buffer->lookupTransform(target, target_time, source, source_time, fixed, timeout);
      });
}

void defineLookups(BufferClass& buffer_class) {
  defineLookupTransform(buffer_class);
  defineCanTransform(buffer_class);
  buffer_class.def(
      "lookup_velocity",
      [](const BufferPtr& buffer, StrArg tracking_frame, StrArg observation_frame, FloatArg time,
         FloatArg averaging_interval) {
        return buffer->lookupVelocity(
            text(tracking_frame, "tracking_frame"), text(observation_frame, "observation_frame"),
            timePoint(time, "time"), duration(averaging_interval, "averaging_interval"));
      },
      py::arg("tracking_frame"), py::arg("observation_frame"), py::arg("time"),
      py::arg("averaging_interval"),
      "Velocity of tracking_frame relative to observation_frame, expressed in "
      "observation_frame, by central difference over `averaging_interval` seconds around "
      "`time` (0.0: the latest), clipped to the data available.");
  buffer_class.def(
      "get_latest_common_time",
      [](const BufferPtr& buffer, StrArg target, StrArg source) {
        return seconds(buffer->getLatestCommonTime(text(target, "target"), text(source, "source")));
      },
      py::arg("target"), py::arg("source"),
      "The latest time (seconds since the epoch) at which every edge between the two frames "
      "has data; 0.0 when the path is all static.");
}

}  // namespace lcmtf::python
