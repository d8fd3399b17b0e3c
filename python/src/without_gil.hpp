#pragma once

// Work done with the GIL released, by any thread. Once the interpreter has begun to shut down,
// a thread other than the one shutting it down that takes the GIL back is ended there, by
// unwinding its stack. That unwinding must meet no destructor taking the GIL back (it would
// call std::terminate) and no exception already on its way: so the GIL is taken back here by
// a plain call, after any exception of the work has been caught, and rethrown after.

#include <pybind11/pybind11.h>

#include <exception>
#include <optional>
#include <type_traits>
#include <utility>

#if defined(__GLIBCXX__)
#include <cxxabi.h>
#endif

namespace lcmtf::python {

/// What `work()` returns (or throws), run with the GIL released; call it with the GIL held.
template <class Work>
auto withoutGil(Work&& work) -> decltype(work()) {
  using Result = decltype(work());
  using Kept = std::conditional_t<std::is_void_v<Result>, bool, std::optional<Result>>;
  Kept result{};
  std::exception_ptr error;
  PyThreadState* const state = PyEval_SaveThread();
  try {
    if constexpr (std::is_void_v<Result>) {
      work();
    } else {
      result.emplace(work());
    }
#if defined(__GLIBCXX__)
  } catch (abi::__forced_unwind&) {
    throw;  // the interpreter ends this thread (its callback took the GIL back at shutdown)
#endif
  } catch (...) {
    error = std::current_exception();
  }
  PyEval_RestoreThread(state);
  if (error) std::rethrow_exception(error);
  if constexpr (!std::is_void_v<Result>) return std::move(*result);
}

}  // namespace lcmtf::python
