"""Scripts that end, or fork, while lcmtf's threads and the user's are at work: each runs in an
interpreter of its own, which must end with status 0 and say nothing on stderr."""

import subprocess
import sys
import textwrap

# An object whose collection sleeps, with the GIL released, once the interpreter has begun to
# shut down: other threads that take the GIL back meanwhile are ended by the interpreter.
SLOW_TO_GO = """\
import time

class SlowToGo:
    def __del__(self):
        time.sleep(0.5)
"""


def run(script, *arguments):
    return subprocess.run([sys.executable, "-c", textwrap.dedent(script), *arguments],
                          capture_output=True, text=True, timeout=60)


def test_a_listener_left_open_is_closed_at_exit_once_its_reporter_returns(udpm_url):
    ended = run("""\
        import sys
        import time

        import lcmtf

        def busy(message):
            print("reporting", flush=True)
            end = time.monotonic() + 0.5
            while time.monotonic() < end:  # holding the GIL, and taking it back at every switch
                pass
            print("reported", flush=True)

        url = sys.argv[1]
        listener = lcmtf.TransformListener(lcmtf.Buffer(), url, allowed_authorities=["trusted"],
                                           reporter=busy)
        with lcmtf.TransformBroadcaster(url, authority="intruder") as intruder:
            for _ in range(500):
                intruder.send_transform(lcmtf.TransformStamped("map", "base", time.time()))
                if listener.statistics().unauthorized:
                    break
                time.sleep(0.01)
        """, udpm_url)
    assert ended.returncode == 0, ended.stderr
    assert ended.stdout == "reporting\nreported\n" and ended.stderr == ""


def test_a_daemon_thread_waiting_in_lookups_when_the_interpreter_ends():
    ended = run(SLOW_TO_GO + """\
import threading

import lcmtf

buffer = lcmtf.Buffer()

def poll():
    while True:
        try:
            buffer.lookup_transform("map", "odom", 0.0, timeout=0.05)
        except lcmtf.TransformException:
            pass

threading.Thread(target=poll, daemon=True).start()
time.sleep(0.1)
slow = SlowToGo()
print("ending", flush=True)
""")
    assert ended.returncode == 0 and ended.stderr == "", ended.stderr
    assert ended.stdout == "ending\n"


def test_a_wait_given_up_at_ctrl_c_that_ends_while_the_interpreter_ends():
    # The wait, abandoned on its thread, holds the buffer's last reference, and with it the
    # buffer's Python reporter, when it ends.
    ended = run(SLOW_TO_GO + """\
import os
import signal
import threading

import lcmtf

buffer = lcmtf.Buffer(reporter=print)
threading.Timer(0.1, os.kill, (os.getpid(), signal.SIGINT)).start()
try:
    buffer.lookup_transform("map", "odom", 0.0, timeout=0.4)
except KeyboardInterrupt:
    print("interrupted", flush=True)
del buffer
slow = SlowToGo()
""")
    assert ended.returncode == 0 and ended.stderr == "", ended.stderr
    assert ended.stdout == "interrupted\n"


def test_a_forked_child_cannot_use_the_listener_it_inherits_and_ends_well(udpm_url):
    ended = run("""\
        import os
        import sys

        import lcmtf

        url = sys.argv[1]
        buffer = lcmtf.Buffer()
        listener = lcmtf.TransformListener(buffer, url)
        broadcaster = lcmtf.StaticTransformBroadcaster(url)
        child = os.fork()
        if child == 0:
            print("child waits:", buffer.can_transform("a", "b", 0.0, timeout=0.1), flush=True)
            try:
                listener.statistics()
            except ValueError as error:
                print("child:", error, flush=True)
            with lcmtf.TransformBroadcaster(url) as own:
                print("child sends:", own.send_transform(lcmtf.TransformStamped("a", "b", 1.0)),
                      flush=True)
            sys.exit(0)
        _, status = os.waitpid(child, 0)
        print("child's status:", status)
        print("parent still listens:", listener.statistics().messages >= 0)
        """, udpm_url)
    assert ended.returncode == 0, ended.stderr
    assert ended.stdout.splitlines() == [
        "child waits: False",
        "child: the listener was opened before this process was forked, and its threads stayed "
        "in the parent process: open another one here",
        "child sends: True",
        "child's status: 0",
        "parent still listens: True",
    ]
