#include "closes_at_exit.hpp"

#include <condition_variable>
#include <mutex>
#include <set>
#include <thread>

#include <pybind11/pybind11.h>

#include "without_gil.hpp"

namespace lcmtf::python {

namespace {

struct Closes {
  std::mutex mutex;
  std::set<ClosedAtExit*> at_exit;
  std::condition_variable later_all_done;
  std::size_t later_running = 0;
};

// Never destroyed: a later close may still run while static objects are torn down.
Closes* all_closes = new Closes;

// One at a time, with the GIL held until the close releases it: while it does, another thread
// may open an object, or destroy one, which forgets its close.
void closeWhatIsStillOpen() {
  for (;;) {
    ClosedAtExit* object = nullptr;
    {
      std::lock_guard<std::mutex> lock(all_closes->mutex);
      if (all_closes->at_exit.empty()) return;
      object = *all_closes->at_exit.begin();
    }
    object->close();  // forgets it
  }
}

void waitForLaterCloses() {
  withoutGil([] {
    std::unique_lock<std::mutex> lock(all_closes->mutex);
    all_closes->later_all_done.wait(lock, [] { return all_closes->later_running == 0; });
  });
}

// In the child, alone: the parent's threads, one of which may have held the mutex, are gone.
void abandonAfterFork() {
  Closes* inherited = all_closes;
  all_closes = new Closes;
  for (ClosedAtExit* object : inherited->at_exit) object->abandonAfterFork();
}

}  // namespace

void closeAtExit(ClosedAtExit& object) {
  std::lock_guard<std::mutex> lock(all_closes->mutex);
  all_closes->at_exit.insert(&object);
}

void forgetCloseAtExit(ClosedAtExit& object) {
  std::lock_guard<std::mutex> lock(all_closes->mutex);
  all_closes->at_exit.erase(&object);
}

void closeLater(std::function<void()> close) {
  Closes* closes = all_closes;
  {
    std::lock_guard<std::mutex> lock(closes->mutex);
    ++closes->later_running;
  }
  std::thread([close = std::move(close), closes]() mutable {
    close();
    close = nullptr;
    std::lock_guard<std::mutex> lock(closes->mutex);
    if (--closes->later_running == 0) closes->later_all_done.notify_all();
  }).detach();
}

void closeEverythingAtExit() {
  namespace py = pybind11;
  py::module_::import("atexit").attr("register")(py::cpp_function([] {
    closeWhatIsStillOpen();
    waitForLaterCloses();
  }));
  py::module_::import("os").attr("register_at_fork")(py::arg("after_in_child") =
                                                         py::cpp_function(&abandonAfterFork));
}

}  // namespace lcmtf::python
