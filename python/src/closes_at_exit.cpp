#include "closes_at_exit.hpp"

#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>

#include <pybind11/pybind11.h>

namespace lcmtf::python {

namespace {

struct Closes {
  std::mutex mutex;
  std::map<std::uint64_t, std::function<void()>> at_exit;  // in the order they were kept
  std::uint64_t next_key = 0;
  std::condition_variable later_all_done;
  std::size_t later_running = 0;
};

// Never destroyed: a later close may still run while static objects are torn down.
Closes& closes() {
  static auto* all = new Closes;
  return *all;
}

// One at a time, with the GIL held until the close releases it: while it does, another thread
// may open an object, or destroy one, which forgets its close.
void closeWhatIsStillOpen() {
  Closes& all = closes();
  for (;;) {
    std::function<void()> close;
    {
      std::lock_guard<std::mutex> lock(all.mutex);
      if (all.at_exit.empty()) return;
      const auto first = all.at_exit.begin();
      close = std::move(first->second);
      all.at_exit.erase(first);
    }
    close();
  }
}

void waitForLaterCloses() {
  pybind11::gil_scoped_release release;
  Closes& all = closes();
  std::unique_lock<std::mutex> lock(all.mutex);
  all.later_all_done.wait(lock, [&] { return all.later_running == 0; });
}

}  // namespace

std::uint64_t closeAtExit(std::function<void()> close) {
  Closes& all = closes();
  std::lock_guard<std::mutex> lock(all.mutex);
  const std::uint64_t key = all.next_key++;
  all.at_exit.emplace(key, std::move(close));
  return key;
}

void forgetCloseAtExit(std::uint64_t key) {
  Closes& all = closes();
  std::lock_guard<std::mutex> lock(all.mutex);
  all.at_exit.erase(key);
}

void closeLater(std::function<void()> close) {
  Closes& all = closes();
  {
    std::lock_guard<std::mutex> lock(all.mutex);
    ++all.later_running;
  }
  std::thread([close = std::move(close), &all]() mutable {
    close();
    close = nullptr;
    std::lock_guard<std::mutex> lock(all.mutex);
    if (--all.later_running == 0) all.later_all_done.notify_all();
  }).detach();
}

void closeEverythingAtExit() {
  pybind11::module_::import("atexit").attr("register")(pybind11::cpp_function([] {
    closeWhatIsStillOpen();
    waitForLaterCloses();
  }));
}

}  // namespace lcmtf::python
