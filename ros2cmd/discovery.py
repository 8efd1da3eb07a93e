"""What each participant announced: ROS 2's ``ros_discovery_info`` topic, read through rmw.

Every ROS 2 process (one DDS participant per rclpy context) publishes on the DDS topic
``ros_discovery_info`` an ``rmw_dds_common/msg/ParticipantEntitiesInfo``: its nodes and, per
node, the GIDs of their readers and writers. It is reliable and transient-local, so a
newcomer receives each participant's latest one. rmw builds the ROS graph from it (node names,
which endpoint belongs to which node) and from DDS endpoint discovery. A tool that knows what
each participant announced can wait until all of it has reached its own graph, instead of
guessing from a quiet period (see graph.Graph.wait_complete).

rclpy cannot subscribe to it: rcl gives every topic name a leading '/', and this DDS topic,
which rmw creates itself, has none. So this module creates the subscription one level lower,
through rmw's C API (ctypes on the rmw library rclpy has loaded), takes serialized samples and
deserializes them with rclpy. It is the only place in the project that goes below rclpy; if
it cannot (another rmw, another ABI), ``DiscoveryInfo.available`` is False and the tools fall
back to waiting one announcement period.
"""

from __future__ import annotations

import ctypes
import os
from contextlib import suppress
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # loaded by DiscoveryInfo, which only a graph node uses
    from rclpy.node import Node
    from rmw_dds_common.msg import ParticipantEntitiesInfo

DISCOVERY_TOPIC = "ros_discovery_info"
FASTDDS_DEFAULT_ANNOUNCEMENT = 3.0  # s, Fast DDS's leaseAnnouncement when no profile sets it


def announcement_period() -> float:
    """How often every running participant announces itself (Fast DDS leaseAnnouncement).

    A participant that started later has heard every running one after this long, even when
    its own first announcements were missed.
    """
    path = os.environ.get("FASTRTPS_DEFAULT_PROFILES_FILE")
    if not path:
        return FASTDDS_DEFAULT_ANNOUNCEMENT
    import xml.etree.ElementTree as ET  # only a list's settle reads the profile

    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return FASTDDS_DEFAULT_ANNOUNCEMENT
    for element in root.iter():
        if element.tag.rsplit("}", 1)[-1] == "leaseAnnouncement":
            parts = {child.tag.rsplit("}", 1)[-1]: (child.text or "0") for child in element}
            with suppress(ValueError):
                return float(parts.get("sec", "0")) + float(parts.get("nanosec", "0")) * 1e-9
    return FASTDDS_DEFAULT_ANNOUNCEMENT


def participant_of(gid: bytes) -> bytes:
    """A DDS GID is the participant's 12-byte GUID prefix plus a 4-byte entity id."""
    return bytes(gid[:12])


class _Time(ctypes.Structure):
    _fields_ = (("sec", ctypes.c_uint64), ("nsec", ctypes.c_uint64))


class _QoS(ctypes.Structure):  # rmw_qos_profile_t (rmw/types.h, Jazzy)
    _fields_ = (
        ("history", ctypes.c_int),
        ("depth", ctypes.c_size_t),
        ("reliability", ctypes.c_int),
        ("durability", ctypes.c_int),
        ("deadline", _Time),
        ("lifespan", _Time),
        ("liveliness", ctypes.c_int),
        ("liveliness_lease_duration", _Time),
        ("avoid_ros_namespace_conventions", ctypes.c_bool),
    )


class _SubscriptionOptions(ctypes.Structure):  # rmw_subscription_options_t (Jazzy)
    _fields_ = (
        ("rmw_specific_subscription_payload", ctypes.c_void_p),
        ("ignore_local_publications", ctypes.c_bool),
        ("require_unique_network_flow_endpoints", ctypes.c_int),
        ("content_filter_options", ctypes.c_void_p),
    )


class _Allocator(ctypes.Structure):  # rcutils_allocator_t
    _fields_ = tuple((name, ctypes.c_void_p) for name in ("a", "d", "r", "z", "state"))


class _Bytes(ctypes.Structure):  # rmw_serialized_message_t = rcutils_uint8_array_t
    _fields_ = (
        ("buffer", ctypes.POINTER(ctypes.c_uint8)),
        ("buffer_length", ctypes.c_size_t),
        ("buffer_capacity", ctypes.c_size_t),
        ("allocator", _Allocator),
    )


_KEEP_LAST, _RELIABLE, _TRANSIENT_LOCAL = 1, 1, 1


class DiscoveryInfo:
    """The latest ParticipantEntitiesInfo of every participant, kept up to date by take()."""

    def __init__(self, node: Node) -> None:
        self.node = node
        self.latest: dict[bytes, ParticipantEntitiesInfo] = {}  # participant prefix -> info
        self._subscription = None
        try:
            self._open()
        except (OSError, AttributeError, ValueError):
            self._subscription = None  # tools fall back to the announcement period

    @property
    def available(self) -> bool:
        return self._subscription is not None

    def _open(self) -> None:
        import rclpy
        from rmw_dds_common.msg import ParticipantEntitiesInfo

        self._rmw = ctypes.CDLL(f"lib{rclpy.get_rmw_implementation_identifier()}.so")
        rcl = ctypes.CDLL("librcl.so")
        rcutils = ctypes.CDLL("librcutils.so")
        rmw_base = ctypes.CDLL("librmw.so")
        rcl.rcl_node_get_rmw_handle.restype = ctypes.c_void_p
        rcl.rcl_node_get_rmw_handle.argtypes = (ctypes.c_void_p,)
        self._rmw_node = rcl.rcl_node_get_rmw_handle(self.node.handle.pointer)
        if not self._rmw_node:
            raise ValueError("no rmw node")
        get_pointer = ctypes.pythonapi.PyCapsule_GetPointer
        get_pointer.restype = ctypes.c_void_p
        get_pointer.argtypes = (ctypes.py_object, ctypes.c_char_p)
        ParticipantEntitiesInfo.__class__.__import_type_support__()
        type_support = get_pointer(ParticipantEntitiesInfo._TYPE_SUPPORT, None)
        rmw_base.rmw_get_default_subscription_options.restype = _SubscriptionOptions
        options = rmw_base.rmw_get_default_subscription_options()
        # As rmw's own reader of this topic, but keeping every participant's sample: the
        # topic has no key, so a depth of 1 would keep only the last participant's.
        qos = _QoS(
            history=_KEEP_LAST,
            depth=1000,
            reliability=_RELIABLE,
            durability=_TRANSIENT_LOCAL,
            avoid_ros_namespace_conventions=True,
        )
        create = self._rmw.rmw_create_subscription
        create.restype = ctypes.c_void_p
        create.argtypes = (
            ctypes.c_void_p,
            ctypes.c_void_p,
            ctypes.c_char_p,
            ctypes.POINTER(_QoS),
            ctypes.POINTER(_SubscriptionOptions),
        )
        self._take = self._rmw.rmw_take_serialized_message
        self._take.argtypes = (
            ctypes.c_void_p,
            ctypes.POINTER(_Bytes),
            ctypes.POINTER(ctypes.c_bool),
            ctypes.c_void_p,
        )
        self._rmw.rmw_destroy_subscription.argtypes = (ctypes.c_void_p, ctypes.c_void_p)
        rcutils.rcutils_get_default_allocator.restype = _Allocator
        self._allocator = rcutils.rcutils_get_default_allocator()
        self._buffer = _Bytes()
        self._rcutils = rcutils
        if rcutils.rcutils_uint8_array_init(
            ctypes.byref(self._buffer), ctypes.c_size_t(0), ctypes.byref(self._allocator)
        ):
            raise ValueError("cannot allocate a buffer")
        subscription = create(
            self._rmw_node,
            type_support,
            DISCOVERY_TOPIC.encode(),
            ctypes.byref(qos),
            ctypes.byref(options),
        )
        if not subscription:
            rcutils.rcutils_uint8_array_fini(ctypes.byref(self._buffer))
            raise ValueError("rmw_create_subscription failed")
        self._subscription = subscription

    def take(self) -> bool:
        """Take every sample that has arrived; True if any did."""
        from rclpy.serialization import deserialize_message
        from rmw_dds_common.msg import ParticipantEntitiesInfo

        if self._subscription is None:
            return False
        changed = False
        while True:
            taken = ctypes.c_bool(False)
            if self._take(
                self._subscription, ctypes.byref(self._buffer), ctypes.byref(taken), None
            ):
                return changed
            if not taken.value:
                return changed
            data = ctypes.string_at(self._buffer.buffer, self._buffer.buffer_length)
            info = deserialize_message(data, ParticipantEntitiesInfo)
            self.latest[participant_of(bytes(info.gid.data))] = info
            changed = True

    def close(self) -> None:
        if self._subscription is not None:
            self._rmw.rmw_destroy_subscription(self._rmw_node, self._subscription)
            self._rcutils.rcutils_uint8_array_fini(ctypes.byref(self._buffer))
            self._subscription = None
