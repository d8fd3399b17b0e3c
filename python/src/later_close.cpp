#include "later_close.hpp"

#include <condition_variable>
#include <mutex>
#include <thread>

#include <pybind11/pybind11.h>

namespace lcmtf::python {

namespace {

struct LaterCloses {
  std::mutex mutex;
  std::condition_variable all_done;
  std::size_t running = 0;
};

// Never destroyed: a close may still run while static objects are torn down.
LaterCloses& laterCloses() {
  static auto* closes = new LaterCloses;
  return *closes;
}

}  // namespace

void closeLater(std::function<void()> close) {
  LaterCloses& closes = laterCloses();
  {
    std::lock_guard<std::mutex> lock(closes.mutex);
    ++closes.running;
  }
  std::thread([close = std::move(close), &closes]() mutable {
    close();
    close = nullptr;
    std::lock_guard<std::mutex> lock(closes.mutex);
    if (--closes.running == 0) closes.all_done.notify_all();
  }).detach();
}

void waitForLaterClosesAtExit() {
  const auto wait = [] {
    pybind11::gil_scoped_release release;
    LaterCloses& closes = laterCloses();
    std::unique_lock<std::mutex> lock(closes.mutex);
    closes.all_done.wait(lock, [&] { return closes.running == 0; });
  };
  pybind11::module_::import("atexit").attr("register")(pybind11::cpp_function(wait));
}

}  // namespace lcmtf::python
