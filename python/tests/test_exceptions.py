"""Each C++ exception arrives in Python as the class of the same name, with the C++ message."""

import pytest

import lcmtf
from conftest import EPOCH


@pytest.fixture
def buffer():
    """map -> odom from EPOCH to EPOCH + 1 s; island -> shore, a tree of its own."""
    buffer = lcmtf.Buffer()
    for t in (0.0, 0.5, 1.0):
        buffer.set_transform(lcmtf.TransformStamped("map", "odom", EPOCH + t), "test")
    buffer.set_transform(lcmtf.TransformStamped("island", "shore", EPOCH), "test", is_static=True)
    return buffer


@pytest.mark.parametrize("error, target, source, time", [
    (lcmtf.LookupException, "map", "atlantis", 0.0),
    (lcmtf.ConnectivityException, "map", "shore", 0.0),
    (lcmtf.PastExtrapolationException, "map", "odom", EPOCH - 1.0),
    (lcmtf.FutureExtrapolationException, "map", "odom", EPOCH + 2.0),
    (lcmtf.InvalidArgumentException, "map", "", 0.0),
])
def test_lookup_raises_the_python_twin_of_the_cpp_exception(buffer, error, target, source, time):
    _, why = buffer.can_transform(target, source, time, return_debug_tuple=True)
    with pytest.raises(error) as raised:
        buffer.lookup_transform(target, source, time)
    assert type(raised.value) is error
    assert str(raised.value) == why  # the C++ message, word for word


def test_a_gap_wider_than_allowed_raises_interpolation_gap(buffer):
    buffer.max_interpolation_gap = 0.25
    with pytest.raises(lcmtf.InterpolationGapException, match="0.500000 s"):
        buffer.lookup_transform("map", "odom", EPOCH + 0.75)


def test_waiting_in_vain_raises_timeout_naming_what_is_missing(buffer):
    with pytest.raises(lcmtf.TimeoutException, match=r"timed out after 0\.050000 s.*atlantis"):
        buffer.lookup_transform("map", "atlantis", 0.0, timeout=0.05)


def test_the_hierarchy_follows_the_cpp_one():
    for error in (lcmtf.LookupException, lcmtf.ConnectivityException,
                  lcmtf.ExtrapolationException, lcmtf.InvalidArgumentException,
                  lcmtf.TimeoutException):
        assert error.__bases__ == (lcmtf.TransformException,)
    for error in (lcmtf.PastExtrapolationException, lcmtf.FutureExtrapolationException,
                  lcmtf.InterpolationGapException):
        assert error.__bases__ == (lcmtf.ExtrapolationException,)
    assert issubclass(lcmtf.TransformException, RuntimeError)
    assert lcmtf.LookupException.__module__ == "lcmtf" and lcmtf.LookupException.__doc__
