#include "released_wait.hpp"

#include <atomic>

namespace lcmtf::python {

namespace {
std::atomic<unsigned long> main_thread{0};
}  // namespace

void rememberMainThread() {
  main_thread =
      py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
}

bool onMainThread() { return PyThread_get_thread_ident() == main_thread.load(); }

}  // namespace lcmtf::python
