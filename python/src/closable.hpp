#pragma once

// Objects with threads or sockets of their own, which Python code closes when it is done
// (close(), or a with block) rather than whenever the garbage collector gets to them.

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include "closes_at_exit.hpp"
#include "lcmtf/transform_listener.hpp"
#include "python_callback.hpp"
#include "without_gil.hpp"

namespace lcmtf::python {

namespace py = pybind11;

/// Whether the caller is a thread `object` owns and joins when destroyed.
template <class Object>
bool onItsThread(const Object&) {
  return false;
}
inline bool onItsThread(const TransformListener& listener) { return listener.onItsThread(); }

/// Makes `object` stop calling back at once, before it is stopped from another thread.
template <class Object>
void stopCallingBack(Object&) {}
inline void stopCallingBack(TransformListener& listener) { listener.stop(); }

template <class Object>
class Closable final : public ClosedAtExit {
 public:
  /// `keep_alive` lives as long as `object` (what it refers to, such as a listener's buffer).
  Closable(std::unique_ptr<Object> object, std::string name,
           std::shared_ptr<const void> keep_alive = nullptr)
      : keep_alive_(std::move(keep_alive)), name_(std::move(name)), object_(std::move(object)) {
    closeAtExit(*this);
  }
  ~Closable() { close(); }
  Closable(const Closable&) = delete;
  Closable& operator=(const Closable&) = delete;

  /// Holds the cell of a callable `object` calls, for the collector to see (collectableCallback).
  void holdCallback(CallableCellPtr cell) { callback_ = std::move(cell); }
  static CallableCell* callbackOf(Closable& closable) { return closable.callback_.get(); }

  Object& get() const {
    if (!object_) throw py::value_error("the " + name_ + " " + closed_);
    return *object_;
  }
  /// Taken out with the GIL held, so that no other thread is using it and any that calls it
  /// next is told it is closed; then stopped with the GIL released, as its thread may be waiting
  /// for the GIL to call back. Closed from its own thread (inside its reporter), it is stopped
  /// from another one, once the call back returns.
  void close() override {
    std::unique_ptr<Object> object = std::move(object_);
    if (!object) return;
    forgetCloseAtExit(*this);
    withoutGil([&] {
      if (!onItsThread(*object)) {
        object.reset();
        return;
      }
      stopCallingBack(*object);
      closeLater([object = std::shared_ptr<Object>(std::move(object)),
                  keep_alive = std::move(keep_alive_)]() mutable {
        object.reset();
        keep_alive.reset();
      });
    });
  }

  void abandonAfterFork() override {
    static_cast<void>(object_.release());
    closed_ =
        "was opened before this process was forked, and its threads stayed in the parent "
        "process: open another one here";
  }

 private:
  std::string closed_ = "is closed";
  std::shared_ptr<const void> keep_alive_;
  std::string name_;
  std::unique_ptr<Object> object_;
  CallableCellPtr callback_;
};

/// close(), and use in a with block, which closes it at the end.
template <class Object>
void defineClose(py::class_<Closable<Object>>& python_class) {
  python_class
      .def("close", &Closable<Object>::close,
           "Stops it and frees its LCM; it cannot be used afterwards. Called at the end of a "
           "with block, by the garbage collector otherwise, and at the interpreter's exit "
           "(after the functions registered with atexit later than lcmtf was imported). "
           "Closed from its own reporter, it calls back and stores nothing more. A child "
           "process made by os.fork() cannot use the ones it inherits.")
      .def(
          "__enter__", [](py::object self) { return self; }, "Returns itself, for a with block.")
      .def(
          "__exit__", [](Closable<Object>& self, const py::args&) { self.close(); },
          "Closes it at the end of a with block.");
}

}  // namespace lcmtf::python
