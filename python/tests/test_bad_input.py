"""Bad input raises TypeError or ValueError naming the argument at fault, and changes nothing."""

import math

import numpy as np
import pytest

import lcmtf

EPOCH = 1_700_000_000.0
GOOD = lcmtf.TransformStamped("map", "base", EPOCH)
POINTS = np.zeros((2, 3))


def stamped(**changes):
    arguments = dict(parent_frame="map", child_frame="base", stamp=EPOCH,
                     translation=(1.0, 2.0, 3.0), rotation=(0.0, 0.0, 0.0, 1.0))
    arguments.update(changes)
    return lambda buffer: lcmtf.TransformStamped(**arguments)


def on_buffer(method, *arguments, **options):
    return lambda buffer: getattr(buffer, method)(*arguments, **options)


CASES = {
    "parent frame an int": (stamped(parent_frame=1), TypeError, "parent_frame"),
    "child frame bytes": (stamped(child_frame=b"base"), TypeError, "child_frame"),
    "parent frame with a NUL": (stamped(parent_frame="map\0x"), ValueError, "parent_frame"),
    "lookup frame with a NUL": (
        on_buffer("lookup_transform", "map", "base\0", 0.0), ValueError, "source"),
    "authority with a NUL": (on_buffer("set_transform", GOOD, "me\0"), ValueError, "authority"),
    "stamp a str": (stamped(stamp="now"), TypeError, "stamp"),
    "stamp NaN": (stamped(stamp=math.nan), ValueError, "stamp"),
    "stamp before 1970": (stamped(stamp=-1.0), ValueError, "stamp"),
    "stamp a bool": (stamped(stamp=True), TypeError, "stamp"),
    "translation too short": (stamped(translation=[1, 2]), ValueError, "translation"),
    "translation NaN": (stamped(translation=[1, 2, math.nan]), ValueError, "translation"),
    "translation a column": (stamped(translation=np.zeros((3, 1))), ValueError, "translation"),
    "translation of str": (stamped(translation=["1", "2", "3"]), TypeError, "translation[0]"),
    "translation complex": (stamped(translation=np.array([1j, 0, 0])), TypeError, "translation"),
    "translation None": (stamped(translation=None), TypeError, "translation"),
    "rotation zero": (stamped(rotation=[0, 0, 0, 0]), ValueError, "rotation"),
    "rotation infinite": (stamped(rotation=[0, 0, math.inf, 1]), ValueError, "rotation"),
    "rotation of three": (stamped(rotation=np.array([0.0, 0.0, 1.0])), ValueError, "rotation"),
    "target an int": (on_buffer("lookup_transform", 1, "base"), TypeError, "target"),
    "source None": (on_buffer("can_transform", "map", None), TypeError, "source"),
    "time a str": (on_buffer("lookup_transform", "map", "base", "0"), TypeError, "time"),
    "time infinite": (on_buffer("lookup_transform", "map", "base", math.inf), ValueError, "time"),
    "timeout negative": (on_buffer("lookup_transform", "map", "base", 0.0, -1.0), ValueError,
                         "timeout"),
    "fixed an int": (on_buffer("lookup_transform", "map", EPOCH, "base", EPOCH, 3), TypeError,
                     "fixed"),
    "timeout of a century": (on_buffer("can_transform", "map", "base", 0.0, 3.2e9), ValueError,
                             "timeout"),
    "target time NaN": (on_buffer("can_transform", "map", math.nan, "base", EPOCH, "odom"),
                        ValueError, "target_time"),
    "points of two columns": (on_buffer("transform_points", np.zeros((4, 2)), "base", "map"),
                              ValueError, "points"),
    "points one point": (on_buffer("transform_points", np.zeros(3), "base", "map"), ValueError,
                         "points"),
    "points complex": (on_buffer("transform_points", np.zeros((2, 3), complex), "base", "map"),
                       TypeError, "points"),
    "points bool": (on_buffer("transform_points", np.zeros((2, 3), bool), "base", "map"),
                    TypeError, "points"),
    "points of str": (on_buffer("transform_points", [["a", "b", "c"]], "base", "map"),
                      TypeError, "points"),
    "points None": (on_buffer("transform_points", None, "base", "map"), TypeError, "points"),
    "points ragged": (on_buffer("transform_points", [[1, 2, 3], [4, 5]], "base", "map"),
                      TypeError, "points"),
    "cloud target an int": (on_buffer("transform_points", POINTS, "base", 5), TypeError,
                            "target_frame"),
    "transform a dict": (on_buffer("set_transform", {"parent_frame": "map"}, "me"), TypeError,
                         "transform"),
    "authority an int": (on_buffer("set_transform", GOOD, 5), TypeError, "authority"),
    "batch with an int": (on_buffer("set_transforms", [GOOD, 5], "me"), TypeError,
                          "transforms[1]"),
    "batch an int": (on_buffer("set_transforms", 5, "me"), TypeError, "transforms"),
    "frame a float": (on_buffer("get_parent", 5.0), TypeError, "frame"),
    "interval negative": (on_buffer("lookup_velocity", "base", "map", 0.0, -0.1), ValueError,
                          "averaging_interval"),
    "cache time zero": (lambda buffer: lcmtf.Buffer(0.0), ValueError, "cache_time"),
    "cache time a str": (lambda buffer: lcmtf.Buffer("10"), TypeError, "cache_time"),
    "listener without buffer": (lambda buffer: lcmtf.TransformListener("memq://"), TypeError,
                                "buffer"),
    "listener URL an int": (lambda buffer: lcmtf.TransformListener(buffer, 7667), TypeError,
                            "lcm_url"),
    "listener frames negative": (
        lambda buffer: lcmtf.TransformListener(buffer, "memq://", max_frames=-1), ValueError,
        "max_frames"),
    "listener queue bytes zero": (
        lambda buffer: lcmtf.TransformListener(buffer, "memq://", queue_bytes=0), ValueError,
        "queue_bytes"),
    "listener stamps ahead negative": (
        lambda buffer: lcmtf.TransformListener(buffer, "memq://", max_stamp_ahead=-1.0),
        ValueError, "max_stamp_ahead"),
    "listener authorities a str": (
        lambda buffer: lcmtf.TransformListener(buffer, "memq://", allowed_authorities="me"),
        TypeError, "allowed_authorities"),
    "listener authorities empty": (
        lambda buffer: lcmtf.TransformListener(buffer, "memq://", allowed_authorities=[]),
        ValueError, "allowed_authorities"),
    "wait timeout a str": (
        lambda buffer: buffer.wait_for_transform("map", "nowhere", 0.0, "x"), TypeError,
        "timeout"),
    "wait timeout negative": (
        lambda buffer: buffer.wait_for_transform("map", "nowhere", 0.0, -1.0), ValueError,
        "timeout"),
    "buffer reporter not callable": (
        lambda buffer: lcmtf.Buffer(reporter="stderr"), TypeError, "reporter"),
    "listener reporter not callable": (
        lambda buffer: lcmtf.TransformListener(buffer, "memq://", reporter="stderr"), TypeError,
        "reporter"),
    "broadcast a str": (
        lambda buffer: lcmtf.TransformBroadcaster("memq://").send_transform("map"), TypeError,
        "transform"),
    "broadcast a name listeners refuse": (
        lambda buffer: lcmtf.TransformBroadcaster("memq://").send_transform(
            lcmtf.TransformStamped("map", "c" * 257, EPOCH)), ValueError, "transform"),
    "broadcast a batch with a name listeners refuse": (
        lambda buffer: lcmtf.TransformBroadcaster("memq://").send_transforms(
            [GOOD, lcmtf.TransformStamped("p" * 300, "base", EPOCH)]), ValueError, "transforms"),
    "broadcaster authority listeners refuse": (
        lambda buffer: lcmtf.StaticTransformBroadcaster("memq://", authority="a" * 257),
        ValueError, "authority"),
    "listener authority listeners refuse": (
        lambda buffer: lcmtf.TransformListener(buffer, "memq://", authority="a" * 257),
        ValueError, "authority"),
    "resend period NaN": (
        lambda buffer: lcmtf.StaticTransformBroadcaster("memq://", resend_period=math.nan),
        ValueError, "resend_period"),
    "utime of a str": (lambda buffer: lcmtf.to_utime("1.5"), TypeError, "time"),
}


@pytest.mark.parametrize("call, error, argument", CASES.values(), ids=CASES.keys())
def test_bad_input_raises_naming_the_argument(call, error, argument):
    buffer = lcmtf.Buffer()
    buffer.set_transform(GOOD, "test")
    with pytest.raises(error) as raised:
        call(buffer)
    assert type(raised.value) is error
    assert str(raised.value).startswith(argument + " "), str(raised.value)
    assert sorted(buffer.frames()) == ["base", "map"]
    assert buffer.statistics().inserted == 1


@pytest.mark.parametrize("time", [math.nan, -1.0, 1e300])
def test_a_time_out_of_range_is_told_the_range(time):
    with pytest.raises(ValueError, match=r"^time must be seconds since the epoch from 0 to 9\.2e12"):
        lcmtf.Buffer().lookup_transform("map", "base", time)


def test_a_closed_listener_says_so():
    listener = lcmtf.TransformListener(lcmtf.Buffer(), "memq://")
    listener.close()
    with pytest.raises(ValueError, match="closed"):
        listener.statistics()
