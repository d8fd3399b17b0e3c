"""Waiting lookups let other Python threads run, wake when the data comes, and stop on Ctrl-C."""

import os
import signal
import threading
import time

import pytest

import lcmtf
from conftest import EPOCH


def insert_later(buffer, delay, parent="map", child="base"):
    """Stores parent -> child at EPOCH after `delay` seconds, from another thread."""
    def insert():
        time.sleep(delay)
        buffer.set_transform(lcmtf.TransformStamped(parent, child, EPOCH, [1, 2, 3]), "late")
    thread = threading.Thread(target=insert)
    thread.start()
    return thread


def test_a_waiting_lookup_returns_once_the_transform_arrives():
    buffer = lcmtf.Buffer()
    inserter = insert_later(buffer, 0.1)
    started = time.monotonic()
    result = buffer.lookup_transform("map", "base", EPOCH, timeout=10.0)
    assert time.monotonic() - started < 5.0
    assert result.translation.tolist() == [1, 2, 3]
    inserter.join()


def test_other_python_threads_run_while_one_waits():
    buffer = lcmtf.Buffer()
    counted = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counted.append(None)
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        assert not buffer.can_transform("map", "base", EPOCH, timeout=0.3)
        during_wait = len(counted)
    finally:
        stop.set()
        counter.join()
    assert during_wait >= 20  # about 300 at 1 ms a step; far fewer had the wait kept the GIL


def test_waiting_on_another_thread_needs_no_signal_checks():
    buffer = lcmtf.Buffer()
    results = []
    waiter = threading.Thread(
        target=lambda: results.append(buffer.lookup_transform("map", "base", EPOCH, timeout=10)))
    waiter.start()
    insert_later(buffer, 0.05).join()
    waiter.join(timeout=5)
    assert results and results[0].child_frame == "base"


def test_ctrl_c_interrupts_a_wait_on_the_main_thread():
    buffer = lcmtf.Buffer()
    timer = threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT))
    started = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        buffer.lookup_transform("map", "base", EPOCH, timeout=30.0)
    assert time.monotonic() - started < 5.0
    timer.join()


def test_wait_for_transform_gives_a_future_that_ends_with_the_transform():
    buffer = lcmtf.Buffer()
    called = []
    future = buffer.wait_for_transform("map", "base", EPOCH, 10.0, callback=called.append)
    assert not future.done()
    insert_later(buffer, 0.05).join()
    assert future.result(timeout=5).translation.tolist() == [1, 2, 3]
    for _ in range(100):  # the callback runs just after the result is set
        if called:
            break
        time.sleep(0.01)
    assert called == [future]


def test_wait_for_transform_ends_with_the_timeout_exception():
    future = lcmtf.Buffer().wait_for_transform("map", "base", EPOCH, 0.05)
    with pytest.raises(lcmtf.TimeoutException, match="timed out after 0.050000 s"):
        future.result(timeout=5)


def test_wait_for_transform_already_available_is_done_at_once():
    buffer = lcmtf.Buffer()
    insert_later(buffer, 0.0).join()
    future = buffer.wait_for_transform("map", "base", EPOCH, 1.0)
    assert future.done() and future.result().parent_frame == "map"


def test_wait_for_transform_checks_its_arguments_at_once():
    with pytest.raises(TypeError, match="^source"):
        lcmtf.Buffer().wait_for_transform("map", 5, EPOCH, 1.0)


def test_time_travel_lookup_waits_for_both_halves():
    buffer = lcmtf.Buffer()
    buffer.set_transform(lcmtf.TransformStamped("odom", "base", EPOCH, [1, 0, 0]), "test")
    insert_later(buffer, 0.1, "odom", "camera")
    result = buffer.lookup_transform("camera", EPOCH, "base", EPOCH, "odom", timeout=10.0)
    assert result.translation.tolist() == [0, -2, -3]
    assert buffer.can_transform("camera", EPOCH, "base", EPOCH, "odom", timeout=1.0)
