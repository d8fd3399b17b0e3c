#include <string>
#include <vector>

#include "bindings.hpp"
#include "lcmtf/insert_statistics.hpp"
#include "lcmtf/transform_listener.hpp"

namespace lcmtf::python {

namespace {

// A class of read-only counters whose repr lists every field by name.
template <class Counts>
class CountsClass {
 public:
  CountsClass(py::module_& module, const char* name, const char* doc)
      : class_(module, name, doc), name_(name) {}

  template <class Field>
  CountsClass& field(const char* name, Field Counts::*member, const char* doc) {
    class_.def_readonly(name, member, doc);
    fields_.push_back(name);
    return *this;
  }
  py::class_<Counts>& finish() {
    class_.def("__repr__", [name = name_, fields = fields_](py::handle self) {
      std::string text = name + "(";
      for (const std::string& field : fields) {
        text += (&field == &fields.front() ? "" : ", ") + field + "=" +
                std::string(py::repr(self.attr(field.c_str())));
      }
      return text + ")";
    });
    return class_;
  }

 private:
  py::class_<Counts> class_;
  std::string name_;
  std::vector<std::string> fields_;
};

py::dict rejectionCounts(const InsertStatistics& statistics) {
  py::dict counts;
  for (std::size_t kind = 0; kind < statistics.rejected.size(); ++kind) {
    counts[describe(static_cast<InsertRejection>(kind))] = statistics.rejected[kind];
  }
  return counts;
}

void bindInsertStatistics(py::module_& module) {
  CountsClass<InsertStatistics>(module, "InsertStatistics",
                                "What a buffer's inserts have done since it was made.")
      .field("inserted", &InsertStatistics::inserted, "Samples stored, static ones included.")
      .field("replaced", &InsertStatistics::replaced,
             "Samples whose stamp repeated an earlier one and replaced it.")
      .field("normalized", &InsertStatistics::normalized, "Quaternions normalized on the way in.")
      .field("authority_conflicts", &InsertStatistics::authority_conflicts,
             "Edges set by another authority than before.")
      .field("dropped_for_room", &InsertStatistics::dropped_for_room,
             "Oldest samples dropped early because their edge held its most.")
      .finish()
      .def_property_readonly("rejected", &rejectionCounts,
                             "Refused samples by reason, e.g. {'non-finite value': 2, ...}.")
      .def_property_readonly(
          "rejected_total", [](const InsertStatistics& s) { return s.rejectedTotal(); },
          "Refused samples, all reasons together.");
}

void bindListenerStatistics(py::module_& module) {
  using S = ListenerStatistics;
  CountsClass<S>(module, "ListenerStatistics",
                 "What a listener has received and refused since it started.")
      .field("messages", &S::messages, "Batches decoded and accepted.")
      .field("transforms", &S::transforms, "Transforms stored in the buffer.")
      .field("malformed", &S::malformed, "Messages that failed to decode.")
      .field("rejected_transforms", &S::rejected_transforms,
             "Transforms the buffer refused (see Buffer.statistics()).")
      .field("unauthorized", &S::unauthorized, "Batches from authorities not allowed.")
      .field("frame_limit", &S::frame_limit, "Transforms refused by max_frames.")
      .field("stale_batches", &S::stale_batches,
             "Batches dropped as older than the cache time behind the newest.")
      .field("history_resets", &S::history_resets,
             "Times a sender's clock jumped back for good and its edges were cleared.")
      .field("cleared_edges", &S::cleared_edges, "Edges whose history those resets dropped.")
      .field("resets_held_back", &S::resets_held_back,
             "Jumps back dropped because that sender reset not long before.")
      .field("lost_batches", &S::lost_batches, "Numbered batches that never came, all senders.")
      .field("reordered_batches", &S::reordered_batches, "Batches that came after a later one.")
      .field("duplicated_batches", &S::duplicated_batches, "Batches that came twice.")
      .field("sequence_restarts", &S::sequence_restarts,
             "Senders whose numbering began again (a restart, a log replayed).")
      .field("authorities_followed", &S::authorities_followed, "Senders followed now.")
      .field("authorities_forgotten", &S::authorities_forgotten,
             "Senders forgotten to make room for new ones.")
      .field("queue_shortened", &S::queue_shortened,
             "Times large messages made LCM hold fewer waiting on a channel (queue_bytes).")
      .field("stamped_ahead", &S::stamped_ahead,
             "Transforms refused as stamped more than max_stamp_ahead ahead of this clock.")
      .finish();
}

void bindAuthorityStatistics(py::module_& module) {
  using S = AuthorityStatistics;
  CountsClass<S>(module, "AuthorityStatistics",
                 "What a listener heard from one sender since it began following it.")
      .field("authority", &S::authority, "The sender's name.")
      .field("batches", &S::batches, "Batches received from it, stale ones included.")
      .field("lost_batches", &S::lost_batches, "Numbers skipped that have not come yet.")
      .field("reordered_batches", &S::reordered_batches, "Batches that came after a later one.")
      .field("duplicated_batches", &S::duplicated_batches, "Batches that came twice.")
      .field("sequence_restarts", &S::sequence_restarts, "Times its numbering began again.")
      .field("stale_batches", &S::stale_batches,
             "Batches dropped as older than the cache time behind its newest.")
      .field("history_resets", &S::history_resets,
             "Times its clock jumped back for good and its edges were cleared.")
      .field("cleared_edges", &S::cleared_edges, "Edges whose history those resets dropped.")
      .field("resets_held_back", &S::resets_held_back,
             "Jumps back dropped because it reset within the cache time.")
      .field("stamped_ahead", &S::stamped_ahead,
             "Its transforms refused as stamped more than max_stamp_ahead ahead of this clock.")
      .finish();
}

}  // namespace

void bindStatistics(py::module_& module) {
  bindInsertStatistics(module);
  bindListenerStatistics(module);
  bindAuthorityStatistics(module);
}

}  // namespace lcmtf::python
