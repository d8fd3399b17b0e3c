#pragma once

// Closing an object from inside its own callback: its thread cannot wait for itself, so another
// thread closes it once the callback returns, and the interpreter waits for that thread before
// it shuts down, as the close may still need the GIL.

#include <functional>

namespace lcmtf::python {

/// Runs `close` on a thread of its own, now; call it without the GIL.
void closeLater(std::function<void()> close);

/// Registers, with Python's atexit, a wait for every close still running.
void waitForLaterClosesAtExit();

}  // namespace lcmtf::python
