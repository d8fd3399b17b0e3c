#pragma once

// Blocking calls made from Python: other Python threads run while one waits, and Ctrl-C
// interrupts a wait on the main thread.

#include <pybind11/pybind11.h>

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <thread>

#include "without_gil.hpp"

namespace lcmtf::python {

namespace py = pybind11;

/// Notes which thread is Python's main thread, the one that runs signal handlers.
void rememberMainThread();
bool onMainThread();

/// How often a wait on the main thread looks for a signal such as Ctrl-C.
inline constexpr std::chrono::milliseconds kSignalCheckPeriod{50};

/// The result of `wait`, run with the GIL released. On the main thread `wait` runs on a thread
/// of its own while this one checks for signals: KeyboardInterrupt abandons it, and it ends by
/// its own timeout. `wait` must therefore own everything it uses.
template <class Result>
Result waitReleased(std::function<Result()> wait) {
  if (!onMainThread()) return withoutGil(wait);
  auto task = std::make_shared<std::packaged_task<Result()>>(std::move(wait));
  std::future<Result> done = task->get_future();
  std::thread([task] { (*task)(); }).detach();
  for (;;) {
    {
      py::gil_scoped_release release;
      if (done.wait_for(kSignalCheckPeriod) == std::future_status::ready) break;
    }
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
  return done.get();
}

}  // namespace lcmtf::python
