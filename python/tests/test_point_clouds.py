"""transform_points moves a whole cloud in one call, exactly as point-by-point lookups would."""

import math

import numpy as np
import pytest

import lcmtf
from conftest import EPOCH, quaternion


@pytest.fixture
def buffer():
    buffer = lcmtf.Buffer()
    for step in range(5):
        t = step / 4
        buffer.set_transform(lcmtf.TransformStamped(
            "odom", "base", EPOCH + t, [t, 2 * t, 0], quaternion(t, [0, 0, 1])), "test")
    buffer.set_transform(lcmtf.TransformStamped(
        "base", "lidar", 0.0, [0.2, 0, 0.9], quaternion(0.3, [1, 2, 3])), "test", is_static=True)
    return buffer


def one_by_one(transform, points):
    return np.array([transform.matrix() @ np.append(p, 1.0) for p in points])[:, :3]


def test_cloud_equals_point_by_point(buffer):
    points = np.random.default_rng(3).uniform(-20, 20, size=(1000, 3))
    moved = buffer.transform_points(points, "lidar", "odom", EPOCH + 0.6)
    odom_T_lidar = buffer.lookup_transform("odom", "lidar", EPOCH + 0.6)
    assert moved.shape == (1000, 3) and moved.dtype == np.float64
    np.testing.assert_allclose(moved, one_by_one(odom_T_lidar, points), rtol=0, atol=1e-12)


def test_time_travel_cloud_equals_point_by_point(buffer):
    points = np.random.default_rng(4).uniform(-5, 5, size=(100, 3))
    moved = buffer.transform_points(points, "lidar", EPOCH + 0.1, "lidar", EPOCH + 0.9, "odom")
    then_T_before = buffer.lookup_transform("lidar", EPOCH + 0.9, "lidar", EPOCH + 0.1, "odom")
    np.testing.assert_allclose(moved, one_by_one(then_T_before, points), rtol=0, atol=1e-12)


def test_any_real_array_of_n_by_3_is_taken(buffer):
    rows = [[1, 2, 3], [4, 5, 6]]
    expected = buffer.transform_points(np.array(rows, dtype=np.float64), "lidar", "base")
    for points in (rows, np.array(rows, dtype=np.float32), np.array(rows, dtype=np.int16),
                   np.asfortranarray(np.array(rows, dtype=np.float64)),
                   np.array([[1, 0, 2, 0, 3], [4, 0, 5, 0, 6]], dtype=np.float64)[:, ::2]):
        np.testing.assert_array_equal(buffer.transform_points(points, "lidar", "base"), expected)


def test_empty_cloud_gives_an_empty_cloud(buffer):
    assert buffer.transform_points(np.empty((0, 3)), "lidar", "odom").shape == (0, 3)


def test_nan_points_stay_nan_and_leave_the_others_alone(buffer):
    points = np.array([[1.0, 2.0, 3.0], [math.nan, 0.0, 0.0]])
    moved = buffer.transform_points(points, "lidar", "base")
    assert np.isfinite(moved[0]).all() and np.isnan(moved[1]).any()


def test_a_cloud_whose_transform_is_missing_raises_as_a_lookup_does(buffer):
    with pytest.raises(lcmtf.FutureExtrapolationException):
        buffer.transform_points(np.zeros((3, 3)), "lidar", "odom", EPOCH + 5)
