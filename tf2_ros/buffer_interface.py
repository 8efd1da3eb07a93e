"""tf2_ros.BufferInterface: ``transform()`` of stamped messages, and the registries behind it.

``buffer.transform(point_stamped, 'world')`` looks up the transform from the message's frame at
its stamp and applies the function registered for the message's type. tf2_geometry_msgs
registers geometry_msgs' stamped types when it is imported (``import tf2_geometry_msgs``), as
upstream's does; an unregistered type raises TypeException("Type ... is not loaded or
supported"). ``convert()`` and ConvertRegistration turn one registered type into another.
"""

from __future__ import annotations

from collections.abc import Callable
from copy import deepcopy
from typing import Any, ClassVar

from rclpy.duration import Duration
from rclpy.time import Time
from std_msgs.msg import Header

__all__ = [
    "BufferInterface",
    "ConvertRegistration",
    "NotImplementedException",
    "Stamped",
    "TransformRegistration",
    "TypeException",
    "convert",
]

NO_TIMEOUT = Duration()  # the default of every timeout: do not wait


class TypeException(Exception):
    """A type with no registered transform or conversion."""

    def __init__(self, errstr: str) -> None:
        super().__init__(errstr)
        self.errstr = errstr


class NotImplementedException(Exception):
    """A BufferInterface without lookups of its own."""

    def __init__(self) -> None:
        self.errstr = "CanTransform or LookupTransform not implemented"
        super().__init__(self.errstr)


class TransformRegistration:
    """Message type -> function(message, TransformStamped) -> message; one table for all."""

    _functions: ClassVar[dict[Any, Callable[[Any, Any], Any]]] = {}

    def add(self, key: Any, callback: Callable[[Any, Any], Any]) -> None:
        TransformRegistration._functions[key] = callback

    def get(self, key: Any) -> Callable[[Any, Any], Any]:
        try:
            return TransformRegistration._functions[key]
        except KeyError:
            raise TypeException(f"Type {key} is not loaded or supported") from None

    def print_me(self) -> None:
        print(TransformRegistration._functions)


class ConvertRegistration:
    """Conversions between registered types: to a message, from a message, or direct."""

    _to_msg: ClassVar[dict[Any, Callable[[Any], Any]]] = {}
    _from_msg: ClassVar[dict[Any, Callable[[Any], Any]]] = {}
    _convert: ClassVar[dict[tuple[Any, Any], Callable[[Any], Any]]] = {}

    def add_to_msg(self, key: Any, callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._to_msg[key] = callback

    def add_from_msg(self, key: Any, callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._from_msg[key] = callback

    def add_convert(self, key: tuple[Any, Any], callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._convert[key] = callback

    @staticmethod
    def _get(table: dict, key: Any) -> Callable[[Any], Any]:
        try:
            return table[key]
        except KeyError:
            raise TypeException(f"Type {key} is not loaded or supported") from None

    def get_to_msg(self, key: Any) -> Callable[[Any], Any]:
        return self._get(ConvertRegistration._to_msg, key)

    def get_from_msg(self, key: Any) -> Callable[[Any], Any]:
        return self._get(ConvertRegistration._from_msg, key)

    def get_convert(self, key: tuple[Any, Any]) -> Callable[[Any], Any]:
        return self._get(ConvertRegistration._convert, key)


def convert(a: Any, b_type: Any) -> Any:
    """A as B_TYPE: a direct conversion if registered, else through the message type."""
    registry = ConvertRegistration()
    try:
        return registry.get_convert((type(a), b_type))(a)
    except TypeException:
        if type(a) is b_type:
            return deepcopy(a)
        return registry.get_from_msg(b_type)(registry.get_to_msg(type(a))(a))


def Stamped(obj: Any, stamp: Time, frame_id: str) -> Any:
    """OBJ with a header of STAMP and FRAME_ID."""
    obj.header = Header(frame_id=frame_id, stamp=stamp)
    return obj


class BufferInterface:
    """What a buffer offers: the lookups (its subclass's) and transform() on top of them."""

    def __init__(self) -> None:
        self.registration = TransformRegistration()

    def transform(
        self,
        object_stamped: Any,
        target_frame: str,
        timeout: Duration = NO_TIMEOUT,
        new_type: Any = None,
    ) -> Any:
        """OBJECT_STAMPED in TARGET_FRAME, at its own stamp (waiting up to TIMEOUT)."""
        do_transform = self.registration.get(type(object_stamped))
        transform = self.lookup_transform(
            target_frame, object_stamped.header.frame_id, object_stamped.header.stamp, timeout
        )
        result = do_transform(object_stamped, transform)
        return result if new_type is None else convert(result, new_type)

    def transform_full(
        self,
        object_stamped: Any,
        target_frame: str,
        target_time: Time,
        fixed_frame: str,
        timeout: Duration = NO_TIMEOUT,
        new_type: Any = None,
    ) -> Any:
        """OBJECT_STAMPED in TARGET_FRAME at TARGET_TIME, through FIXED_FRAME."""
        do_transform = self.registration.get(type(object_stamped))
        transform = self.lookup_transform_full(
            target_frame,
            target_time,
            object_stamped.header.frame_id,
            object_stamped.header.stamp,
            fixed_frame,
            timeout,
        )
        result = do_transform(object_stamped, transform)
        return result if new_type is None else convert(result, new_type)

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Time, timeout: Duration = NO_TIMEOUT
    ) -> Any:
        raise NotImplementedException()

    def lookup_transform_full(
        self,
        target_frame: str,
        target_time: Time,
        source_frame: str,
        source_time: Time,
        fixed_frame: str,
        timeout: Duration = NO_TIMEOUT,
    ) -> Any:
        raise NotImplementedException()

    def can_transform(
        self, target_frame: str, source_frame: str, time: Time, timeout: Duration = NO_TIMEOUT
    ) -> bool:
        raise NotImplementedException()

    def can_transform_full(
        self,
        target_frame: str,
        target_time: Time,
        source_frame: str,
        source_time: Time,
        fixed_frame: str,
        timeout: Duration = NO_TIMEOUT,
    ) -> bool:
        raise NotImplementedException()
