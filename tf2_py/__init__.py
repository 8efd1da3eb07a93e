"""tf2_py: tf2's transform core, as the tf2_py binding names it (BufferCore and the exceptions).

ROS 2 Jazzy's tf2 (C++) and its Python binding are not on PyPI; this is the same core in plain
Python: a tree of frames, a time cache per frame (10 s by default), linear interpolation of
translation and slerp of rotation, lookups through the common parent (buffer_core.py,
time_cache.py). tf2_ros.Buffer builds on it, as upstream's does on the binding.
"""

from tf2_py.buffer_core import BufferCore
from tf2_py.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)

__all__ = [
    "BufferCore",
    "ConnectivityException",
    "ExtrapolationException",
    "InvalidArgumentException",
    "LookupException",
    "TimeoutException",
    "TransformException",
]
