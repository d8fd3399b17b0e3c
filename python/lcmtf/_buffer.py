"""Buffer: the compiled buffer plus waiting in the background with a future."""

import concurrent.futures
import threading

from . import _lcmtf


class Buffer(_lcmtf.Buffer):
    __doc__ = _lcmtf.Buffer.__doc__

    def lookup_transform_full(self, target, target_time, source, source_time, fixed,
                              timeout=0.0):
        """lookup_transform's time-travel form, under the name tf2_ros gives it."""
        return self.lookup_transform(target, target_time, source, source_time, fixed, timeout)

    def can_transform_full(self, target, target_time, source, source_time, fixed, timeout=0.0,
                           *, return_debug_tuple=False):
        """can_transform's time-travel form, under the name tf2_ros gives it."""
        return self.can_transform(target, target_time, source, source_time, fixed, timeout,
                                  return_debug_tuple=return_debug_tuple)

    def wait_for_transform(self, target, source, time, timeout, callback=None):
        """A concurrent.futures.Future of lookup_transform(target, source, time, timeout).

        The wait runs on a thread of its own; the future ends with the TransformStamped or
        with the lookup's exception (TimeoutException once `timeout` seconds have passed).
        `callback(future)`, when given, is called once it has ended, from the thread that
        ended it (at once, from this one, when the transform is already available). The
        interpreter waits for a pending wait at exit, at most its timeout.
        """
        available = self.can_transform(target, source, time)  # bad arguments raise here
        _lcmtf._check_timeout(timeout)
        future = concurrent.futures.Future()
        if callback is not None:
            future.add_done_callback(callback)
        future.set_running_or_notify_cancel()

        def wait():
            try:
                result = self.lookup_transform(target, source, time, timeout)
            except BaseException as error:  # the future's owner decides what it means
                future.set_exception(error)
            else:
                future.set_result(result)

        if available:
            wait()
        else:
            threading.Thread(target=wait, name="lcmtf.wait_for_transform").start()
        return future


Buffer.__module__ = "lcmtf"
