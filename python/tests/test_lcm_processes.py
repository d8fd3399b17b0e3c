"""lcmtf in Python and C++ programs talk over udpm (ttl=0, a port of each test's own): a Python
listener hears C++ publishers, and a C++ listener hears Python broadcasters."""

import functools
import gc
import math
import re
import subprocess
import threading
import time
import weakref

import numpy as np
import pytest

import lcmtf
from conftest import pose_matrix, quaternion

MOUNTS = """\
transforms:
  - {frame_id: base, child_frame_id: camera, x: 0.1, z: 0.5, yaw: 1.5707963267948966}
  - {frame_id: camera, child_frame_id: camera_optical, qx: -0.5, qy: 0.5, qz: -0.5, qw: 0.5}
"""
base_T_optical = pose_matrix([0.1, 0, 0.5], quaternion(math.pi / 2, [0, 0, 1])) @ pose_matrix(
    [0, 0, 0], [-0.5, 0.5, -0.5, 0.5])


def odom_T_base(stamp, origin_utime):
    """The transport peer's motion: a straight line at constant speed while turning at a
    constant rate about a fixed axis, which interpolation reproduces exactly."""
    s = (lcmtf.to_utime(stamp) - origin_utime) * 1e-6
    translation = np.array([1.0, 2.0, 0.3]) + s * np.array([0.5, -0.25, 0.1])
    return pose_matrix(translation, quaternion(0.8 * s, [1, 2, 2]))


def test_python_listener_hears_cpp_static_publisher_and_broadcaster(
        udpm_url, program, start, tmp_path):
    (tmp_path / "mounts.yaml").write_text(MOUNTS)
    buffer = lcmtf.Buffer()
    with lcmtf.TransformListener(buffer, udpm_url) as listener:
        start(program("LCMTF_STATIC_PUBLISHER"), "--lcm-url", udpm_url,
              "--file", tmp_path / "mounts.yaml")
        origin = lcmtf.to_utime(time.time())
        start(program("LCMTF_TRANSPORT_PEER"), "dynamic", udpm_url, 100, 20000, origin, 1.0)

        latest = buffer.lookup_transform("odom", "camera_optical", 0.0, timeout=10.0)
        np.testing.assert_allclose(
            latest.matrix(), odom_T_base(latest.stamp, origin) @ base_T_optical, atol=1e-9)
        between = buffer.lookup_transform("odom", "camera_optical", latest.stamp + 0.0537,
                                          timeout=10.0)
        np.testing.assert_allclose(
            between.matrix(), odom_T_base(between.stamp, origin) @ base_T_optical, atol=1e-9)

        statistics = listener.statistics()
        assert statistics.messages >= 2 and statistics.malformed == 0
        assert statistics.queue_shortened == 0  # batches of the usual size keep the whole queue
        senders = [s.authority for s in listener.authority_statistics()]
        assert any(name.startswith("lcmtf-static-publisher@") for name in senders), senders


def test_cpp_listener_hears_python_broadcasters(udpm_url, program):
    map_T_odom = lcmtf.TransformStamped("map", "odom", 0.0, [10, 0, 0],
                                        quaternion(math.pi / 2, [0, 0, 1]))
    odom_T_base = lcmtf.TransformStamped("odom", "base", 0.0, [1, 2, 0],
                                         quaternion(0.3, [0, 0, 1]))
    stop = threading.Event()
    with lcmtf.StaticTransformBroadcaster(udpm_url) as statics, \
            lcmtf.TransformBroadcaster(udpm_url) as broadcaster:
        assert statics.send_transform(map_T_odom) and len(statics) == 1

        def broadcast():
            while not stop.is_set():
                odom_T_base.stamp = time.time()
                broadcaster.send_transforms([odom_T_base])
                stop.wait(0.02)

        sender = threading.Thread(target=broadcast)
        sender.start()
        try:
            echo = subprocess.run(
                [program("LCMTF_ECHO"), "--lcm-url", udpm_url, "--once", "--timeout", "10",
                 "--precision", "9", "map", "base"],
                capture_output=True, text=True, timeout=60)
        finally:
            stop.set()
            sender.join()
    assert echo.returncode == 0, echo.stderr

    def numbers(label):
        found = re.search(label + r"\s+\[([^\]]*)\]", echo.stdout)
        assert found, echo.stdout
        return [float(value) for value in found.group(1).split(",")]

    expected = map_T_odom.matrix() @ odom_T_base.matrix()
    np.testing.assert_allclose(numbers(r"translation \(m\)"), expected[:3, 3], atol=1e-8)
    reported = pose_matrix([0, 0, 0], numbers("quaternion xyzw"))
    np.testing.assert_allclose(reported[:3, :3], expected[:3, :3], atol=1e-8)


def refuse_intruders_until(udpm_url, done):
    with lcmtf.TransformBroadcaster(udpm_url, authority="intruder") as broadcaster:
        for _ in range(200):
            broadcaster.send_transform(lcmtf.TransformStamped("map", "base", time.time()))
            if done.wait(0.01):
                return
    raise AssertionError("the listener's reporter was never called")


@pytest.mark.parametrize("how", ["close", "drop the last reference"])
def test_a_listener_closed_from_inside_its_own_reporter_stops(udpm_url, how):
    holder = {}
    done = threading.Event()

    def close_it(message):
        if how == "close":
            holder["listener"].close()
        else:
            del holder["listener"]
        done.set()

    holder["listener"] = lcmtf.TransformListener(lcmtf.Buffer(), udpm_url,
                                                 allowed_authorities=["trusted"],
                                                 reporter=close_it)
    refuse_intruders_until(udpm_url, done)
    if how == "close":
        with pytest.raises(ValueError, match="closed"):
            holder["listener"].statistics()
    else:
        assert "listener" not in holder


@pytest.mark.parametrize("kind", ["listener", "broadcaster", "static broadcaster"])
def test_closed_while_another_thread_uses_it_that_thread_is_told_it_is_closed(udpm_url, kind):
    for _ in range(20):
        if kind == "listener":
            closable = lcmtf.TransformListener(lcmtf.Buffer(), udpm_url)
            use = closable.statistics
        else:
            broadcaster = (lcmtf.TransformBroadcaster if kind == "broadcaster"
                           else lcmtf.StaticTransformBroadcaster)
            closable = broadcaster(udpm_url)
            transform = lcmtf.TransformStamped("map", "base", time.time())
            use = functools.partial(closable.send_transform, transform)
        errors = []
        using = threading.Event()

        def keep_using():
            try:
                while True:
                    use()
                    using.set()
            except ValueError as error:
                errors.append(str(error))

        user = threading.Thread(target=keep_using)
        user.start()
        assert using.wait(10.0)
        closable.close()
        user.join(10.0)
        assert not user.is_alive() and len(errors) == 1 and "is closed" in errors[0], errors


def test_a_listener_closed_inside_its_reporter_stores_nothing_it_had_queued(udpm_url):
    buffer = lcmtf.Buffer()
    holder, reports = {}, []

    def close_it(message):
        reports.append(message)
        holder["listener"].close()

    holder["listener"] = lcmtf.TransformListener(buffer, udpm_url, reporter=close_it)
    with lcmtf.TransformBroadcaster(udpm_url) as broadcaster:
        now = time.time()
        broadcaster.send_transform(lcmtf.TransformStamped("odom", "ahead", now + 3600))
        for i in range(50):  # queued behind the refusal, on one socket
            broadcaster.send_transform(lcmtf.TransformStamped("odom", f"base{i}", now))
        for _ in range(500):
            if reports:
                break
            time.sleep(0.01)
        time.sleep(0.2)
    assert len(reports) == 1 and "ahead of this machine's clock" in reports[0], reports
    assert buffer.frames() == []


def test_listener_reports_a_refusal_to_a_python_callable(udpm_url):
    reports = []
    buffer = lcmtf.Buffer()
    with lcmtf.TransformListener(buffer, udpm_url, allowed_authorities=["trusted"],
                                 reporter=reports.append) as listener, \
            lcmtf.TransformBroadcaster(udpm_url, authority="intruder") as broadcaster:
        for _ in range(200):
            broadcaster.send_transform(lcmtf.TransformStamped("map", "base", time.time()))
            if reports:
                break
            time.sleep(0.01)
        assert listener.statistics().unauthorized >= 1
    assert len(reports) == 1 and "'intruder'" in reports[0], reports
    assert not buffer.frame_exists("base")


def test_a_reporter_may_ask_its_listener_for_the_statistics(udpm_url):
    holder, seen = {}, []
    done = threading.Event()

    def report(message):
        seen.append(holder["listener"].statistics().unauthorized)
        done.set()

    holder["listener"] = lcmtf.TransformListener(lcmtf.Buffer(), udpm_url,
                                                 allowed_authorities=["trusted"], reporter=report)
    with holder["listener"]:
        refuse_intruders_until(udpm_url, done)
    assert seen == [1]


def test_a_transform_the_buffer_refuses_goes_to_the_buffers_reporter(udpm_url):
    listener_reports, buffer_reports = [], []
    buffer = lcmtf.Buffer(reporter=buffer_reports.append)
    far_from_unit = lcmtf.TransformStamped("map", "base", time.time(), rotation=(0, 0, 0, 2))
    with lcmtf.TransformListener(buffer, udpm_url, reporter=listener_reports.append), \
            lcmtf.TransformBroadcaster(udpm_url) as broadcaster:
        for _ in range(200):
            broadcaster.send_transform(far_from_unit)
            if buffer_reports:
                break
            time.sleep(0.01)
    assert len(buffer_reports) == 1 and "quaternion of norm 2" in buffer_reports[0], buffer_reports
    assert listener_reports == []


def test_a_transform_stamped_an_hour_ahead_is_refused_and_the_edge_keeps_its_publisher(udpm_url):
    reports = []
    buffer = lcmtf.Buffer()
    start = time.time()
    with lcmtf.TransformListener(buffer, udpm_url, reporter=reports.append) as listener, \
            lcmtf.TransformBroadcaster(udpm_url, authority="odometry") as odometry, \
            lcmtf.TransformBroadcaster(udpm_url, authority="clock_ahead") as ahead:
        odometry.send_transform(lcmtf.TransformStamped("odom", "base", start, [1, 0, 0]))
        assert buffer.can_transform("odom", "base", start, timeout=5.0)
        ahead.send_transform(lcmtf.TransformStamped("odom", "base", start + 3600, [-999, 0, 0]))
        for _ in range(500):
            if listener.statistics().stamped_ahead:
                break
            time.sleep(0.01)
        odometry.send_transform(lcmtf.TransformStamped("odom", "base", start + 0.01, [2, 0, 0]))
        assert buffer.can_transform("odom", "base", start + 0.01, timeout=5.0)
        assert buffer.lookup_transform("odom", "base", 0.0).translation[0] == 2.0
        assert listener.statistics().stamped_ahead == 1
        senders = {s.authority: s.stamped_ahead for s in listener.authority_statistics()}
        assert senders == {"odometry": 0, "clock_ahead": 1}, senders
    assert buffer.statistics().rejected_total == 0
    assert len(reports) == 1 and "from 'clock_ahead'" in reports[0], reports


def test_an_object_whose_method_is_its_listeners_reporter_is_collected_and_the_listener_stops():
    class Node:
        def __init__(self):
            self.buffer = lcmtf.Buffer()
            self.listener = lcmtf.TransformListener(self.buffer, "memq://", reporter=self.report)

        def report(self, message):
            pass

    node = Node()
    gone, listener_gone = weakref.ref(node), weakref.ref(node.listener)
    del node
    gc.collect()
    assert gone() is None and listener_gone() is None
