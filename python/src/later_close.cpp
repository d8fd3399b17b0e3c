#include "later_close.hpp"

#include <algorithm>
#include <list>
#include <mutex>
#include <thread>

#include <pybind11/pybind11.h>

namespace lcmtf::python {

namespace {

struct LaterCloses {
  std::mutex mutex;
  std::list<std::thread> threads;
  std::list<std::thread::id> finished;
};

// Never destroyed: a close may still run while static objects are torn down.
LaterCloses& laterCloses() {
  static auto* closes = new LaterCloses;
  return *closes;
}

// Joins the threads that have finished, so the list holds only those still closing.
void joinFinished(LaterCloses& closes) {
  for (const std::thread::id id : closes.finished) {
    const auto done =
        std::find_if(closes.threads.begin(), closes.threads.end(),
                     [id](const std::thread& thread) { return thread.get_id() == id; });
    if (done != closes.threads.end()) {
      done->join();
      closes.threads.erase(done);
    }
  }
  closes.finished.clear();
}

}  // namespace

void closeLater(std::function<void()> close) {
  LaterCloses& closes = laterCloses();
  std::lock_guard<std::mutex> lock(closes.mutex);
  joinFinished(closes);
  closes.threads.emplace_back([close = std::move(close), &closes]() mutable {
    close();
    close = nullptr;
    std::lock_guard<std::mutex> done(closes.mutex);
    closes.finished.push_back(std::this_thread::get_id());
  });
}

void waitForLaterClosesAtExit() {
  const auto wait = [] {
    pybind11::gil_scoped_release release;
    LaterCloses& closes = laterCloses();
    std::list<std::thread> running;
    {
      std::lock_guard<std::mutex> lock(closes.mutex);
      running.swap(closes.threads);
      closes.finished.clear();
    }
    for (std::thread& thread : running) thread.join();
  };
  pybind11::module_::import("atexit").attr("register")(pybind11::cpp_function(wait));
}

}  // namespace lcmtf::python
