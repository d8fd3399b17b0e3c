#include "lcmtf/transform_listener.hpp"

#include <pybind11/stl.h>

#include <climits>

#include "arguments.hpp"
#include "bindings.hpp"
#include "buffer_class.hpp"
#include "closable.hpp"
#include "python_callback.hpp"

namespace lcmtf::python {

namespace {

using Listener = Closable<TransformListener>;

BufferPtr bufferArgument(py::handle value) {
  if (!py::isinstance<Buffer>(value)) {
    throw py::type_error(std::string("buffer must be an lcmtf.Buffer, not ") +
                         Py_TYPE(value.ptr())->tp_name);
  }
  return value.cast<BufferPtr>();
}

std::unique_ptr<Listener> makeListener(
    py::handle buffer_arg, OptionalStrArg lcm_url, StrArg channel, StrArg static_channel,
    StrArg static_request_channel, bool static_only, py::handle allowed_authorities,
    IntArg max_frames, IntArg max_authorities, IntArg queue_capacity, IntArg queue_bytes,
    OptionalStrArg authority, bool request_statics_at_start, FloatArg max_interpolation_gap,
    FloatArg max_stamp_ahead, IntArg max_name_bytes, IntArg max_array_elements,
    py::handle reporter) {
  const BufferPtr buffer = bufferArgument(buffer_arg);
  const ListenerOptions defaults;
  ListenerOptions options;
  options.lcm_url = textOr(lcm_url, "lcm_url", "");
  options.channel = text(channel, "channel");
  options.static_channel = text(static_channel, "static_channel");
  options.static_request_channel = text(static_request_channel, "static_request_channel");
  options.static_only = static_only;
  options.allowed_authorities = textList(allowed_authorities, "allowed_authorities");
  if (!allowed_authorities.is_none() && options.allowed_authorities.empty()) {
    throw py::value_error(
        "allowed_authorities is empty: it would refuse every sender (None accepts all)");
  }
  options.max_frames = count(max_frames, "max_frames", 1);
  options.max_authorities = count(max_authorities, "max_authorities", 1);
  options.queue_capacity = static_cast<int>(count(queue_capacity, "queue_capacity", 1, INT_MAX));
  options.queue_bytes = count(queue_bytes, "queue_bytes", 1);
  options.authority = sendableTextOr(authority, "authority", defaults.authority);
  options.request_statics_at_start = request_statics_at_start;
  options.max_interpolation_gap = duration(max_interpolation_gap, "max_interpolation_gap");
  options.max_stamp_ahead = duration(max_stamp_ahead, "max_stamp_ahead");
  options.limits.max_name_bytes = count(max_name_bytes, "max_name_bytes", 1);
  options.limits.max_array_elements = count(max_array_elements, "max_array_elements", 1);
  CallableCellPtr report = callableArgument(reporter, "reporter");
  options.reporter =
      report ? messageCallback(report, "lcmtf listener reporter") : defaults.reporter;
  auto listener = std::make_unique<TransformListener>(*buffer, std::move(options));
  auto closable = std::make_unique<Listener>(std::move(listener), "listener", buffer);
  closable->holdCallback(std::move(report));
  return closable;
}

}  // namespace

void bindListener(py::module_& module) {
  const ListenerOptions defaults;
  py::class_<Listener> listener_class(
      module, "TransformListener", collectableCallback<Listener, &Listener::callbackOf>(),
      "Feeds a Buffer from the TF and TF_STATIC channels on a thread of its own, and asks "
      "static broadcasters to resend when it starts. Nothing from the network can crash it or "
      "corrupt the buffer: bad input is counted in statistics() and reported once per kind.");
  listener_class.def(
      py::init(&makeListener), py::arg("buffer"), py::arg("lcm_url") = py::none(), py::kw_only(),
      py::arg("channel") = defaults.channel, py::arg("static_channel") = defaults.static_channel,
      py::arg("static_request_channel") = defaults.static_request_channel,
      py::arg("static_only") = defaults.static_only, py::arg("allowed_authorities") = py::none(),
      py::arg("max_frames") = defaults.max_frames,
      py::arg("max_authorities") = defaults.max_authorities,
      py::arg("queue_capacity") = defaults.queue_capacity,
      py::arg("queue_bytes") = defaults.queue_bytes, py::arg("authority") = py::none(),
      py::arg("request_statics_at_start") = defaults.request_statics_at_start,
      py::arg("max_interpolation_gap") = seconds(defaults.max_interpolation_gap),
      py::arg("max_stamp_ahead") = seconds(defaults.max_stamp_ahead),
      py::arg("max_name_bytes") = defaults.limits.max_name_bytes,
      py::arg("max_array_elements") = defaults.limits.max_array_elements,
      py::arg("reporter") = py::none(),
      "Listens on its own LCM at `lcm_url` (None: LCM's default, $LCM_DEFAULT_URL or "
      "udpm://239.255.76.67:7667?ttl=0). static_only ignores the dynamic channel; "
      "allowed_authorities (None: all) names the senders accepted; max_frames bounds the frame "
      "names it adds; max_authorities the senders it follows; queue_capacity the messages LCM "
      "queues per channel, fewer while larger messages come than fit in queue_bytes; `authority` "
      "names it in its requests (None: program@host:pid); "
      "request_statics_at_start False leaves request_statics() to the caller; "
      "max_interpolation_gap (seconds, 0.0 for none) is set on the buffer; dynamic transforms "
      "stamped more than max_stamp_ahead seconds ahead of this machine's clock are refused "
      "(0.0: no limit), as one would make its edge refuse its publishers until then; "
      "max_name_bytes and "
      "max_array_elements bound incoming messages; `reporter(message)` gets the first message "
      "of each kind the listener refuses (None: printed on stderr), from the listener's thread; "
      "transforms the buffer refuses go to the buffer's reporter (see Buffer).");
  listener_class.def(
      "request_statics", [](const Listener& self) { self.get().requestStatics(); },
      "Asks every static broadcaster to resend its set now.");
  listener_class.def(
      "statistics", [](const Listener& self) { return self.get().statistics(); },
      "What it has received and refused since it started (ListenerStatistics).");
  listener_class.def(
      "authority_statistics", [](const Listener& self) { return self.get().authorityStatistics(); },
      "Per sender followed now (AuthorityStatistics): those heard more than once first, each "
      "group the most recent first.");
  defineClose(listener_class);
}

}  // namespace lcmtf::python
