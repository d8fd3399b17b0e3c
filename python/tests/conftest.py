"""Fixtures shared by the lcmtf Python tests: poses in closed form, private LCM URLs, and
programs started for a test and stopped after it."""

import math
import os
import subprocess
import zlib

import numpy as np
import pytest

EPOCH = 1_700_000_000.0


def quaternion(angle, axis):
    """The unit quaternion (x, y, z, w) of a rotation by `angle` about `axis`."""
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    return np.append(math.sin(angle / 2) * axis, math.cos(angle / 2))


def rotation_matrix(q):
    """The 3x3 matrix of a unit quaternion (x, y, z, w), written out independently of lcmtf."""
    x, y, z, w = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def pose_matrix(translation, q):
    """The 4x4 homogeneous matrix of a pose."""
    matrix = np.eye(4)
    matrix[:3, :3] = rotation_matrix(q)
    matrix[:3, 3] = translation
    return matrix


@pytest.fixture
def udpm_url(request):
    """A udpm URL with ttl=0 on a port of this test's own, so parallel tests never meet."""
    seed = zlib.crc32(request.node.nodeid.encode()) ^ (os.getpid() * 2654435761)
    # Below the kernel's ephemeral ports (from 32768), which any socket may hold without
    # SO_REUSEADDR: LCM's bind of such a port fails, and it cannot receive.
    return f"udpm://239.255.76.67:{20000 + seed % 12000}?ttl=0"


@pytest.fixture
def program():
    """The path of a program the build made, from the environment ctest sets."""
    def path(variable):
        value = os.environ.get(variable)
        if not value:
            pytest.fail(f"{variable} is not set: run the Python tests through ctest")
        return value
    return path


@pytest.fixture
def start():
    """Starts a program for this test; every program started is killed when the test ends."""
    started = []

    def run(*arguments, **options):
        process = subprocess.Popen([str(a) for a in arguments], **options)
        started.append(process)
        return process

    yield run
    for process in started:
        if process.poll() is None:
            process.kill()
        process.wait()
