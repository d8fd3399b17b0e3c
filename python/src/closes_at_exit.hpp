#pragma once

// What the interpreter's exit waits for. Listeners and broadcasters still open are closed at
// exit, before the interpreter stops other threads from taking the GIL: a listener's thread
// taking it after that, to call its reporter, would be ended in the middle of the call. And an
// object closed from inside its own callback is closed by another thread, as its own cannot wait
// for itself; the exit waits for that thread, as the close may still need the GIL.

#include <cstdint>
#include <functional>

namespace lcmtf::python {

/// Keeps `close` to be called at exit; returns the key that forgets it. With the GIL held.
std::uint64_t closeAtExit(std::function<void()> close);
/// Forgets the close kept under `key`, if it is still kept. With the GIL held.
void forgetCloseAtExit(std::uint64_t key);

/// Runs `close` on a thread of its own, now; call it without the GIL.
void closeLater(std::function<void()> close);

/// Registers with Python's atexit the closes kept, then a wait for every later close.
void closeEverythingAtExit();

}  // namespace lcmtf::python
