"""A buffer filled by hand answers lookups, introspection and velocity as in closed form."""

import copy
import gc
import math
import pickle
import sys
import weakref

import numpy as np
import pytest

import lcmtf
from conftest import EPOCH, pose_matrix, quaternion


def turning_buffer():
    """map -> base turns about z at 1 rad/s and slides along x at 2 m/s from EPOCH to EPOCH + 1;
    base -> camera is static."""
    buffer = lcmtf.Buffer()
    for step in range(11):
        t = step / 10
        buffer.set_transform(lcmtf.TransformStamped(
            "map", "base", EPOCH + t, [2 * t, 0, 0], quaternion(t, [0, 0, 1])), "driver")
    buffer.set_transform(lcmtf.TransformStamped(
        "base", "camera", 0.0, [0.1, 0.2, 0.5], quaternion(-math.pi / 2, [1, 0, 0])),
        "mounts", is_static=True)
    return buffer


def map_T_camera(t):
    return pose_matrix([2 * t, 0, 0], quaternion(t, [0, 0, 1])) @ pose_matrix(
        [0.1, 0.2, 0.5], quaternion(-math.pi / 2, [1, 0, 0]))


def test_lookup_between_samples_interpolates_the_motion():
    result = turning_buffer().lookup_transform("map", "camera", EPOCH + 0.437)
    assert result.parent_frame == "map" and result.child_frame == "camera"
    assert result.stamp == pytest.approx(EPOCH + 0.437, abs=1e-6)
    np.testing.assert_allclose(result.matrix(), map_T_camera(0.437), atol=1e-12)


def test_lookup_at_zero_gives_the_latest_common_time():
    buffer = turning_buffer()
    result = buffer.lookup_transform("camera", "map")
    assert result.stamp == EPOCH + 1.0
    assert buffer.get_latest_common_time("camera", "map") == EPOCH + 1.0
    np.testing.assert_allclose(result.matrix(), np.linalg.inv(map_T_camera(1.0)), atol=1e-12)


def test_time_travel_goes_through_the_fixed_frame():
    buffer = turning_buffer()
    result = buffer.lookup_transform("camera", EPOCH + 0.9, "camera", EPOCH + 0.2, "map")
    expected = np.linalg.inv(map_T_camera(0.9)) @ map_T_camera(0.2)
    np.testing.assert_allclose(result.matrix(), expected, atol=1e-12)
    assert buffer.can_transform("camera", EPOCH + 0.9, "camera", EPOCH + 0.2, "map")


def test_the_full_names_of_tf2_ros_are_time_travel_too():
    buffer = turning_buffer()
    arguments = ("camera", EPOCH + 0.9, "camera", EPOCH + 0.2, "map")
    assert buffer.lookup_transform_full(*arguments) == buffer.lookup_transform(*arguments)
    assert buffer.can_transform_full(*arguments)
    available, why = buffer.can_transform_full("camera", EPOCH + 5, "camera", EPOCH, "map",
                                               return_debug_tuple=True)
    assert not available and "extrapolation into the future" in why.lower(), why
    with pytest.raises(lcmtf.ExtrapolationException):
        buffer.lookup_transform_full("camera", EPOCH + 5, "camera", EPOCH, "map")


def test_transform_stamped_holds_what_it_was_given():
    t = lcmtf.TransformStamped("a", "b", EPOCH + 0.25, (1, 2, 3), (0, 0, 0.6, 0.8))
    assert (t.parent_frame, t.child_frame, t.stamp) == ("a", "b", EPOCH + 0.25)
    assert t.translation.tolist() == [1, 2, 3] and t.rotation.tolist() == [0, 0, 0.6, 0.8]
    with pytest.raises(ValueError):
        t.translation[0] = 5.0  # a copy that cannot be written: assign the whole vector
    t.translation = np.array([4.0, 5.0, 6.0])
    t.child_frame = "c"
    assert t.translation.tolist() == [4, 5, 6] and t.child_frame == "c"
    np.testing.assert_allclose(t.matrix(), pose_matrix([4, 5, 6], [0, 0, 0.6, 0.8]), atol=1e-15)
    assert "child_frame='c'" in repr(t)


def test_transform_stamped_compares_copies_and_pickles_by_value():
    original = lcmtf.TransformStamped("map", "base", EPOCH + 0.123456, [1, 2, 3],
                                      [0, 0, math.sin(0.1), math.cos(0.1)])
    for copied in (pickle.loads(pickle.dumps(original)), copy.copy(original),
                   copy.deepcopy(original)):
        assert copied == original and copied is not original
        assert copied.stamp == original.stamp
    moved = copy.copy(original)
    moved.translation = [1, 2, 3.5]
    assert moved != original
    assert original != lcmtf.TransformStamped("map", "base", EPOCH + 0.123457, [1, 2, 3],
                                              original.rotation)
    assert original != "map -> base"
    with pytest.raises(TypeError):
        hash(original)


def test_times_convert_to_and_from_lcm_microseconds():
    assert lcmtf.to_utime(EPOCH + 0.000250) == 1_700_000_000_000_250
    assert lcmtf.from_utime(1_700_000_000_000_250) == EPOCH + 0.000250
    assert lcmtf.to_utime(lcmtf.from_utime(1_234_567_890_123_456)) == 1_234_567_890_123_456


def test_can_transform_says_why_not():
    buffer = turning_buffer()
    assert buffer.can_transform("map", "camera", EPOCH + 0.5)
    assert buffer.can_transform("map", "camera", EPOCH + 0.5, return_debug_tuple=True) == (
        True, "")
    ok, why = buffer.can_transform("map", "camera", EPOCH + 2.0, return_debug_tuple=True)
    assert not ok and "extrapolation into the future" in why
    assert buffer.can_transform("map", "nowhere") is False


def test_introspection_lists_frames_parents_and_statistics():
    buffer = turning_buffer()
    assert sorted(buffer.frames()) == ["base", "camera", "map"]
    assert buffer.frame_exists("camera") and not buffer.frame_exists("lidar")
    assert buffer.get_parent("camera") == "base"
    assert buffer.get_parent("map") is None
    assert "camera" in buffer.all_frames_as_yaml() and "digraph" in buffer.all_frames_as_dot()
    statistics = buffer.statistics()
    assert statistics.inserted == 12 and statistics.rejected_total == 0
    assert buffer.cache_time == 10.0


def test_refused_samples_are_counted_not_stored():
    buffer = lcmtf.Buffer()
    same = lcmtf.TransformStamped("a", "a", EPOCH)
    far_from_unit = lcmtf.TransformStamped("a", "b", EPOCH, rotation=(0, 0, 0, 2))
    assert buffer.set_transform(same, "test") is False
    batch = [far_from_unit, lcmtf.TransformStamped("a", "c", EPOCH)]
    assert buffer.set_transforms(batch, "test") == 1
    rejected = buffer.statistics().rejected
    assert sum(rejected.values()) == 2 and rejected["frame is its own parent"] == 1
    assert sorted(buffer.frames()) == ["a", "c"]


def test_the_first_refusal_of_each_kind_goes_to_the_buffers_reporter():
    reports = []
    buffer = lcmtf.Buffer(reporter=reports.append)
    assert buffer.set_transform(lcmtf.TransformStamped("a", "a", EPOCH), "test") is False
    assert buffer.set_transform(lcmtf.TransformStamped("b", "b", EPOCH), "test") is False
    far_from_unit = lcmtf.TransformStamped("a", "b", EPOCH, rotation=(0, 0, 0, 2))
    assert buffer.set_transforms([far_from_unit, far_from_unit], "test") == 0
    assert len(reports) == 2, reports
    assert "'a'" in reports[0] and "own parent" in reports[0]
    assert "quaternion of norm 2" in reports[1]


def test_a_reporter_that_raises_does_not_undo_the_refusal(monkeypatch):
    def broken(message):
        raise RuntimeError("reporter broke")

    unraisable = []
    monkeypatch.setattr(sys, "unraisablehook", unraisable.append)
    buffer = lcmtf.Buffer(reporter=broken)
    assert buffer.set_transform(lcmtf.TransformStamped("a", "a", EPOCH), "test") is False
    assert [str(u.exc_value) for u in unraisable] == ["reporter broke"]
    assert buffer.set_transform(lcmtf.TransformStamped("a", "b", EPOCH), "test") is True
    assert buffer.statistics().rejected["frame is its own parent"] == 1


def test_an_object_whose_method_is_its_own_buffers_reporter_is_collected():
    class Node:
        def __init__(self):
            self.buffer = lcmtf.Buffer(reporter=self.report)
            self.reports = []

        def report(self, message):
            self.reports.append(message)

    node = Node()
    node.buffer.set_transform(lcmtf.TransformStamped("a", "a", EPOCH), "test")
    assert len(node.reports) == 1
    gone = weakref.ref(node)
    del node
    gc.collect()
    assert gone() is None


def test_a_collection_while_a_subclass_is_being_initialized_is_safe():
    class Collecting(lcmtf.Buffer):
        def __init__(self, reporter=None):
            gc.collect()  # this object is tracked, and its C++ buffer is not made yet
            super().__init__(reporter=reporter)

    reports = []
    for i in range(50):
        buffer = Collecting(reporter=reports.append if i % 2 else lambda message: None)
        assert buffer.set_transform(lcmtf.TransformStamped("a", "a", EPOCH), "test") is False
        assert buffer.frames() == []
    assert len(reports) == 25


def test_velocity_of_the_turning_base():
    velocity = turning_buffer().lookup_velocity("base", "map", EPOCH + 0.5, 0.2)
    assert velocity.frame == "map"
    np.testing.assert_allclose(velocity.linear, [2, 0, 0], atol=1e-9)
    np.testing.assert_allclose(velocity.angular, [0, 0, 1], atol=1e-9)


def test_cache_time_bounds_the_history_kept():
    buffer = lcmtf.Buffer(cache_time=0.5)
    for step in range(11):
        buffer.set_transform(lcmtf.TransformStamped("map", "base", EPOCH + step / 10), "test")
    assert not buffer.can_transform("map", "base", EPOCH + 0.3)
    assert buffer.can_transform("map", "base", EPOCH + 0.6)
