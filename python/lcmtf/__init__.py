"""Coordinate frames over time for processes that talk over LCM.

A TransformListener fills a Buffer from the TF and TF_STATIC channels; the buffer answers
where any frame was in any other at any stored time::

    import lcmtf
    buffer = lcmtf.Buffer()
    listener = lcmtf.TransformListener(buffer)
    map_T_camera = buffer.lookup_transform("map", "camera", image_time, timeout=0.1)
    in_map = buffer.transform_points(points, "camera", "map", image_time)

Times are float seconds since the epoch (time.time()); 0.0 asks for the latest time every
edge on the path has data. from_utime() and to_utime() convert LCM's integer microseconds.
The LCM message types (tf_message_t, transform_t, joint_state_t, ...) are here too, for
decoding the channels with LCM's own Python module.
"""

from ._lcmtf import (
    AuthorityStatistics,
    ConnectivityException,
    ExtrapolationException,
    FutureExtrapolationException,
    InsertStatistics,
    InterpolationGapException,
    InvalidArgumentException,
    ListenerStatistics,
    LookupException,
    PastExtrapolationException,
    StaticTransformBroadcaster,
    TimeoutException,
    TransformBroadcaster,
    TransformException,
    TransformListener,
    TransformStamped,
    Velocity,
    from_utime,
    to_utime,
)
from ._buffer import Buffer
from ._message_types import (
    joint_state_t,
    quaternion_t,
    resend_request_t,
    robot_description_t,
    tf_message_t,
    transform_t,
    vector3_t,
)

__all__ = [
    "AuthorityStatistics",
    "Buffer",
    "ConnectivityException",
    "ExtrapolationException",
    "FutureExtrapolationException",
    "InsertStatistics",
    "InterpolationGapException",
    "InvalidArgumentException",
    "ListenerStatistics",
    "LookupException",
    "PastExtrapolationException",
    "StaticTransformBroadcaster",
    "TimeoutException",
    "TransformBroadcaster",
    "TransformException",
    "TransformListener",
    "TransformStamped",
    "Velocity",
    "from_utime",
    "joint_state_t",
    "quaternion_t",
    "resend_request_t",
    "robot_description_t",
    "tf_message_t",
    "to_utime",
    "transform_t",
    "vector3_t",
]

for _name in __all__:
    _value = globals()[_name]
    if getattr(_value, "__module__", "").startswith("lcmtf._lcmtf"):
        _value.__module__ = "lcmtf"
del _name, _value
