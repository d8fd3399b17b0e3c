#pragma once

// What the interpreter's exit, and a fork, do to the objects that have threads of their own.
// Listeners and broadcasters still open are closed at exit, before the interpreter stops other
// threads from taking the GIL: a listener's thread taking it after that, to call its reporter,
// would be ended in the middle of the call. An object closed from inside its own callback is
// closed by another thread, as its own cannot wait for itself; the exit waits for that thread,
// as the close may still need the GIL. A child process made by os.fork() has none of its
// parent's threads: it abandons the objects it inherits, which it could neither use nor stop.

#include <functional>

namespace lcmtf::python {

/// An object the exit closes, or a forked child abandons.
class ClosedAtExit {
 public:
  virtual void close() = 0;
  /// Gives the object up without stopping it (its threads are not in this process).
  virtual void abandonAfterFork() = 0;

 protected:
  ~ClosedAtExit() = default;
};

/// Keeps `object` for the exit. With the GIL held.
void closeAtExit(ClosedAtExit& object);
/// Forgets `object`, if it is still kept. With the GIL held.
void forgetCloseAtExit(ClosedAtExit& object);

/// Runs `close` on a thread of its own, now; call it without the GIL.
void closeLater(std::function<void()> close);

/// Registers with Python's atexit the closes kept, then a wait for every later close; and with
/// os.register_at_fork, the abandoning in a child.
void closeEverythingAtExit();

}  // namespace lcmtf::python
