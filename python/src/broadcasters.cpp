#include "arguments.hpp"
#include "bindings.hpp"
#include "closable.hpp"
#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf/transform_broadcaster.hpp"

namespace lcmtf::python {

namespace {

using Dynamic = Closable<TransformBroadcaster>;
using Static = Closable<StaticTransformBroadcaster>;

// A name the broadcaster cannot send is refused naming the argument that held it.
template <class Send>
bool sendNaming(const char* argument, Send send) {
  try {
    return send();
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string(argument) + " cannot be sent: " + e.what());
  }
}

// send_transform, send_transforms and authority, which both broadcasters have.
template <class Broadcaster>
void defineSending(py::class_<Closable<Broadcaster>>& broadcaster_class, const char* one_doc,
                   const char* many_doc) {
  using Python = Closable<Broadcaster>;
  broadcaster_class
      .def(
          "send_transform",
          [](const Python& self, py::handle transform) {
            return sendNaming("transform", [&] {
              return self.get().sendTransform(transformStamped(transform, "transform"));
            });
          },
          py::arg("transform"), one_doc)
      .def(
          "send_transforms",
          [](const Python& self, py::handle transforms) {
            return sendNaming("transforms", [&] {
              return self.get().sendTransform(transformStampedList(transforms, "transforms"));
            });
          },
          py::arg("transforms"), many_doc)
      .def_property_readonly(
          "authority", [](const Python& self) { return self.get().authority(); },
          "The name its batches are signed with.");
  defineClose(broadcaster_class);
}

std::unique_ptr<Dynamic> makeDynamic(OptionalStrArg lcm_url, StrArg channel,
                                     OptionalStrArg authority) {
  return std::make_unique<Dynamic>(std::make_unique<TransformBroadcaster>(
                                       textOr(lcm_url, "lcm_url", ""), text(channel, "channel"),
                                       sendableTextOr(authority, "authority", defaultAuthority())),
                                   "broadcaster");
}

std::unique_ptr<Static> makeStatic(OptionalStrArg lcm_url, StrArg channel, StrArg request_channel,
                                   OptionalStrArg authority, FloatArg resend_period) {
  StaticBroadcasterOptions options;
  options.lcm_url = textOr(lcm_url, "lcm_url", "");
  options.channel = text(channel, "channel");
  options.request_channel = text(request_channel, "request_channel");
  options.authority = sendableTextOr(authority, "authority", options.authority);
  options.resend_period = duration(resend_period, "resend_period");
  return std::make_unique<Static>(std::make_unique<StaticTransformBroadcaster>(options),
                                  "static broadcaster");
}

void bindDynamic(py::module_& module) {
  py::class_<Dynamic> broadcaster_class(
      module, "TransformBroadcaster",
      "Publishes dynamic transforms: one numbered tf_message_t per send_transform or "
      "send_transforms call.");
  broadcaster_class
      .def(py::init(&makeDynamic), py::arg("lcm_url") = py::none(), py::arg("channel") = kTfChannel,
           py::arg("authority") = py::none(),
           "Publishes on its own LCM at `lcm_url` (None: LCM's default), on `channel`, signed "
           "`authority` (None: program@host:pid).")
      .def_property_readonly(
          "channel", [](const Dynamic& self) { return self.get().channel(); },
          "The channel it publishes on.");
  defineSending(broadcaster_class, "Publishes `transform`; False when LCM could not publish.",
                "Publishes the transforms as one batch; False when LCM could not publish.");
}

void bindStatic(py::module_& module) {
  const StaticBroadcasterOptions defaults;
  py::class_<Static> broadcaster_class(
      module, "StaticTransformBroadcaster",
      "Publishes a set of static transforms, keyed by child frame: the whole set on every "
      "change, at once when a listener asks on the request channel, and again every "
      "resend_period seconds, from a thread of its own.");
  broadcaster_class
      .def(py::init(&makeStatic), py::arg("lcm_url") = py::none(),
           py::arg("channel") = defaults.channel,
           py::arg("request_channel") = defaults.request_channel, py::arg("authority") = py::none(),
           py::arg("resend_period") = seconds(defaults.resend_period),
           "Publishes on its own LCM at `lcm_url` (None: LCM's default), on `channel`, answers "
           "requests on request_channel, signs with `authority` (None: program@host:pid) and "
           "resends every resend_period seconds (0.0: only on change and on request).")
      .def(
          "__len__", [](const Static& self) { return self.get().size(); },
          "How many transforms the set holds.")
      .def_property_readonly(
          "requests_answered", [](const Static& self) { return self.get().requestsAnswered(); },
          "Requests from listeners answered so far.");
  defineSending(broadcaster_class,
                "Adds or replaces the transform of its child frame, then publishes the whole "
                "set; False when LCM could not publish.",
                "Adds or replaces the transforms of these child frames, then publishes the "
                "whole set; False when LCM could not publish.");
}

}  // namespace

void bindBroadcasters(py::module_& module) {
  bindDynamic(module);
  bindStatic(module);
}

}  // namespace lcmtf::python
