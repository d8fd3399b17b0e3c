from concurrent.futures import Future
from typing import Callable, Final, Iterable, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from .joint_state_t import joint_state_t as joint_state_t
from .quaternion_t import quaternion_t as quaternion_t
from .resend_request_t import resend_request_t as resend_request_t
from .robot_description_t import robot_description_t as robot_description_t
from .tf_message_t import tf_message_t as tf_message_t
from .transform_t import transform_t as transform_t
from .vector3_t import vector3_t as vector3_t

Vector = Union[Sequence[float], npt.NDArray[np.floating]]
FloatArray = npt.NDArray[np.float64]

class TransformException(RuntimeError): ...
class LookupException(TransformException): ...
class ConnectivityException(TransformException): ...
class ExtrapolationException(TransformException): ...
class PastExtrapolationException(ExtrapolationException): ...
class FutureExtrapolationException(ExtrapolationException): ...
class InterpolationGapException(ExtrapolationException): ...
class InvalidArgumentException(TransformException): ...
class TimeoutException(TransformException): ...

def from_utime(utime: int) -> float: ...
def to_utime(time: float) -> int: ...

class TransformStamped:
    parent_frame: str
    child_frame: str
    stamp: float
    def __init__(
        self,
        parent_frame: str,
        child_frame: str,
        stamp: float = 0.0,
        translation: Vector = (0.0, 0.0, 0.0),
        rotation: Vector = (0.0, 0.0, 0.0, 1.0),
    ) -> None: ...
    @property
    def translation(self) -> FloatArray: ...
    @translation.setter
    def translation(self, xyz: Vector) -> None: ...
    @property
    def rotation(self) -> FloatArray: ...
    @rotation.setter
    def rotation(self, xyzw: Vector) -> None: ...
    def matrix(self) -> FloatArray: ...
    def __eq__(self, other: object) -> bool: ...

class Velocity:
    stamp: Final[float]
    frame: Final[str]
    linear: Final[FloatArray]
    angular: Final[FloatArray]

class InsertStatistics:
    inserted: Final[int]
    replaced: Final[int]
    normalized: Final[int]
    authority_conflicts: Final[int]
    dropped_for_room: Final[int]
    rejected: Final[dict[str, int]]
    rejected_total: Final[int]

class ListenerStatistics:
    messages: Final[int]
    transforms: Final[int]
    malformed: Final[int]
    rejected_transforms: Final[int]
    unauthorized: Final[int]
    frame_limit: Final[int]
    stale_batches: Final[int]
    history_resets: Final[int]
    cleared_edges: Final[int]
    resets_held_back: Final[int]
    lost_batches: Final[int]
    reordered_batches: Final[int]
    duplicated_batches: Final[int]
    sequence_restarts: Final[int]
    authorities_followed: Final[int]
    authorities_forgotten: Final[int]
    queue_shortened: Final[int]
    stamped_ahead: Final[int]

class AuthorityStatistics:
    authority: Final[str]
    batches: Final[int]
    lost_batches: Final[int]
    reordered_batches: Final[int]
    duplicated_batches: Final[int]
    sequence_restarts: Final[int]
    stale_batches: Final[int]
    history_resets: Final[int]
    cleared_edges: Final[int]
    resets_held_back: Final[int]
    stamped_ahead: Final[int]

class Buffer:
    def __init__(
        self, cache_time: float = 10.0, *, reporter: Optional[Callable[[str], object]] = None
    ) -> None: ...
    @property
    def cache_time(self) -> float: ...
    @property
    def max_interpolation_gap(self) -> float: ...
    @max_interpolation_gap.setter
    def max_interpolation_gap(self, gap: float) -> None: ...
    def set_transform(
        self, transform: TransformStamped, authority: str, is_static: bool = False
    ) -> bool: ...
    def set_transforms(
        self, transforms: Iterable[TransformStamped], authority: str, is_static: bool = False
    ) -> int: ...
    def clear(self) -> None: ...
    @overload
    def lookup_transform(
        self, target: str, source: str, time: float = 0.0, timeout: float = 0.0
    ) -> TransformStamped: ...
    @overload
    def lookup_transform(
        self,
        target: str,
        target_time: float,
        source: str,
        source_time: float,
        fixed: str,
        timeout: float = 0.0,
    ) -> TransformStamped: ...
    def lookup_transform_full(
        self,
        target: str,
        target_time: float,
        source: str,
        source_time: float,
        fixed: str,
        timeout: float = 0.0,
    ) -> TransformStamped: ...
    @overload
    def can_transform_full(
        self,
        target: str,
        target_time: float,
        source: str,
        source_time: float,
        fixed: str,
        timeout: float = 0.0,
        *,
        return_debug_tuple: Literal[False] = False,
    ) -> bool: ...
    @overload
    def can_transform_full(
        self,
        target: str,
        target_time: float,
        source: str,
        source_time: float,
        fixed: str,
        timeout: float = 0.0,
        *,
        return_debug_tuple: Literal[True],
    ) -> Tuple[bool, str]: ...
    @overload
    def can_transform(
        self,
        target: str,
        source: str,
        time: float = 0.0,
        timeout: float = 0.0,
        *,
        return_debug_tuple: Literal[False] = False,
    ) -> bool: ...
    @overload
    def can_transform(
        self,
        target: str,
        source: str,
        time: float = 0.0,
        timeout: float = 0.0,
        *,
        return_debug_tuple: Literal[True],
    ) -> Tuple[bool, str]: ...
    @overload
    def can_transform(
        self,
        target: str,
        target_time: float,
        source: str,
        source_time: float,
        fixed: str,
        timeout: float = 0.0,
        *,
        return_debug_tuple: Literal[False] = False,
    ) -> bool: ...
    @overload
    def can_transform(
        self,
        target: str,
        target_time: float,
        source: str,
        source_time: float,
        fixed: str,
        timeout: float = 0.0,
        *,
        return_debug_tuple: Literal[True],
    ) -> Tuple[bool, str]: ...
    def wait_for_transform(
        self,
        target: str,
        source: str,
        time: float,
        timeout: float,
        callback: Optional[Callable[[Future[TransformStamped]], object]] = None,
    ) -> Future[TransformStamped]: ...
    def lookup_velocity(
        self,
        tracking_frame: str,
        observation_frame: str,
        time: float,
        averaging_interval: float,
    ) -> Velocity: ...
    def get_latest_common_time(self, target: str, source: str) -> float: ...
    @overload
    def transform_points(
        self,
        points: npt.ArrayLike,
        source_frame: str,
        target_frame: str,
        time: float = 0.0,
        timeout: float = 0.0,
    ) -> FloatArray: ...
    @overload
    def transform_points(
        self,
        points: npt.ArrayLike,
        source_frame: str,
        source_time: float,
        target_frame: str,
        target_time: float,
        fixed_frame: str,
        timeout: float = 0.0,
    ) -> FloatArray: ...
    def frames(self) -> list[str]: ...
    def frame_exists(self, frame: str) -> bool: ...
    def get_parent(self, frame: str, time: float = 0.0) -> Optional[str]: ...
    def all_frames_as_yaml(self) -> str: ...
    def all_frames_as_dot(self) -> str: ...
    def statistics(self) -> InsertStatistics: ...

class TransformListener:
    def __init__(
        self,
        buffer: Buffer,
        lcm_url: Optional[str] = None,
        *,
        channel: str = "TF",
        static_channel: str = "TF_STATIC",
        static_request_channel: str = "TF_STATIC_REQUEST",
        static_only: bool = False,
        allowed_authorities: Optional[Iterable[str]] = None,
        max_frames: int = 10000,
        max_authorities: int = 1000,
        queue_capacity: int = 1000,
        queue_bytes: int = 67108864,
        authority: Optional[str] = None,
        request_statics_at_start: bool = True,
        max_interpolation_gap: float = 0.0,
        max_stamp_ahead: float = 10.0,
        max_name_bytes: int = 256,
        max_array_elements: int = 65536,
        reporter: Optional[Callable[[str], object]] = None,
    ) -> None: ...
    def request_statics(self) -> None: ...
    def statistics(self) -> ListenerStatistics: ...
    def authority_statistics(self) -> list[AuthorityStatistics]: ...
    def close(self) -> None: ...
    def __enter__(self) -> TransformListener: ...
    def __exit__(self, *args: object) -> None: ...

class TransformBroadcaster:
    def __init__(
        self, lcm_url: Optional[str] = None, channel: str = "TF", authority: Optional[str] = None
    ) -> None: ...
    @property
    def authority(self) -> str: ...
    @property
    def channel(self) -> str: ...
    def send_transform(self, transform: TransformStamped) -> bool: ...
    def send_transforms(self, transforms: Iterable[TransformStamped]) -> bool: ...
    def close(self) -> None: ...
    def __enter__(self) -> TransformBroadcaster: ...
    def __exit__(self, *args: object) -> None: ...

class StaticTransformBroadcaster:
    def __init__(
        self,
        lcm_url: Optional[str] = None,
        channel: str = "TF_STATIC",
        request_channel: str = "TF_STATIC_REQUEST",
        authority: Optional[str] = None,
        resend_period: float = 1.0,
    ) -> None: ...
    @property
    def authority(self) -> str: ...
    @property
    def requests_answered(self) -> int: ...
    def send_transform(self, transform: TransformStamped) -> bool: ...
    def send_transforms(self, transforms: Iterable[TransformStamped]) -> bool: ...
    def __len__(self) -> int: ...
    def close(self) -> None: ...
    def __enter__(self) -> StaticTransformBroadcaster: ...
    def __exit__(self, *args: object) -> None: ...
