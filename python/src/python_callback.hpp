#pragma once

// A Python callable called from a C++ thread, held where the garbage collector can see it.

#include <pybind11/pybind11.h>

#include <exception>
#include <functional>
#include <memory>
#include <string>

namespace lcmtf::python {

namespace py = pybind11;

/// The one strong reference C++ holds to a callback; read and written with the GIL held. The
/// Python object owning it visits it from tp_traverse and drops it in tp_clear (see
/// collectableCallback), so a cycle through it, such as an object that passes its own method
/// and holds the owner, is collected instead of leaking.
struct CallableCell {
  py::object callable;
};
using CallableCellPtr = std::shared_ptr<CallableCell>;

inline bool interpreterShuttingDown() {
#if PY_VERSION_HEX >= 0x030D0000
  return Py_IsFinalizing();
#else
  return _Py_IsFinalizing();
#endif
}

/// Frees a cell, whichever thread drops its last reference. A thread without the GIL leaves it
/// to Python's main thread, which frees it with the GIL held at its next chance: taking the GIL
/// here, from a thread of lcmtf's (a wait given up at Ctrl-C, a listener closed later) while
/// the interpreter shuts down, would end the thread inside this deleter. Such a thread leaves
/// the cell to the process's end once the shutdown has begun, as does any after it.
inline void deleteCell(CallableCell* cell) {
  if (!Py_IsInitialized()) return;
  if (PyGILState_Check()) {
    delete cell;
    return;
  }
  const auto free_cell = [](void* pending) {
    delete static_cast<CallableCell*>(pending);
    return 0;
  };
  if (!interpreterShuttingDown()) Py_AddPendingCall(free_cell, cell);
}

/// The cell of `value`: null when it is None, TypeError naming `argument` when it is not
/// callable.
inline CallableCellPtr callableArgument(py::handle value, const char* argument) {
  if (value.is_none()) return nullptr;
  if (!PyCallable_Check(value.ptr())) {
    throw py::type_error(std::string(argument) + " must be callable or None, not " +
                         Py_TYPE(value.ptr())->tp_name);
  }
  return CallableCellPtr(new CallableCell{py::reinterpret_borrow<py::object>(value)}, &deleteCell);
}

/// Calls the cell's callable with the message, the GIL taken, from whichever thread calls it;
/// nothing once the collector has dropped it. An exception it raises is printed as unraisable
/// (it has no caller to go to).
inline std::function<void(const std::string&)> messageCallback(CallableCellPtr cell,
                                                               const char* context) {
  return [cell = std::move(cell), context](const std::string& message) {
    py::gil_scoped_acquire gil;
    const py::object callable = cell->callable;
    if (!callable || callable.is_none()) return;
    try {
      callable(message);
    } catch (py::error_already_set& error) {
      error.discard_as_unraisable(context);
    }
  };
}

/// The cell a Python object of a bound type holds, or null when it holds none or its C++
/// object is not made yet (the collector may look while __init__ runs). Read from the
/// instance's own record: casting would have pybind11 allocate the missing C++ object, in the
/// middle of a collection, and hand back memory nobody constructed.
template <class Cpp, CallableCell* (*CellOf)(Cpp&)>
CallableCell* cellIn(PyObject* self) {
  auto* instance = reinterpret_cast<py::detail::instance*>(self);
  const py::detail::value_and_holder held = instance->get_value_and_holder();
  if (!held.holder_constructed() || held.value_ptr() == nullptr) return nullptr;
  return CellOf(*held.value_ptr<Cpp>());
}

/// Makes the objects of a bound type visible to the garbage collector through the callable
/// `CellOf(object)` holds (null: none).
template <class Cpp, CallableCell* (*CellOf)(Cpp&)>
py::custom_type_setup collectableCallback() {
  return py::custom_type_setup([](PyHeapTypeObject* heap_type) {
    PyTypeObject* type = &heap_type->ht_type;
    type->tp_flags |= Py_TPFLAGS_HAVE_GC;
    type->tp_traverse = [](PyObject* self, visitproc visit, void* arg) -> int {
      Py_VISIT(Py_TYPE(self));
      if (CallableCell* cell = cellIn<Cpp, CellOf>(self)) Py_VISIT(cell->callable.ptr());
      return 0;
    };
    type->tp_clear = [](PyObject* self) -> int {
      if (CallableCell* cell = cellIn<Cpp, CellOf>(self)) cell->callable = py::none();
      return 0;
    };
  });
}

}  // namespace lcmtf::python
