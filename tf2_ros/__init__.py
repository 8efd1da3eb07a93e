"""tf2_ros: tf2's ROS API for rclpy, by the names ROS 2 code imports.

``from tf2_ros import TransformBroadcaster, StaticTransformBroadcaster, TransformException``,
``from tf2_ros.buffer import Buffer``, ``from tf2_ros.transform_listener import
TransformListener``: the names upstream's package exports (its modules, and tf2_py's core and
exceptions), and ``TransformStamped``, which Jazzy's tf2_ros hands on from geometry_msgs through
its modules' star imports (``from tf2_ros import TransformBroadcaster, TransformStamped``, as the
URDF page's state_publisher.py writes). ROS 2 Jazzy's tf2_ros is not on PyPI; this one runs on
this project's tf2_py.

Its commands are the modules here with a main(): `ros2 run tf2_ros tf2_echo`,
`static_transform_publisher`, `tf2_monitor` (ros_tutorials_common/packages.py finds them).
"""

from geometry_msgs.msg import TransformStamped

from tf2_py import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from tf2_ros.buffer import Buffer
from tf2_ros.buffer_interface import (
    BufferInterface,
    ConvertRegistration,
    NotImplementedException,
    Stamped,
    TransformRegistration,
    TypeException,
    convert,
)
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf2_ros.transform_broadcaster import TransformBroadcaster
from tf2_ros.transform_listener import TransformListener

__all__ = [
    "Buffer",
    "BufferCore",
    "BufferInterface",
    "ConnectivityException",
    "ConvertRegistration",
    "ExtrapolationException",
    "InvalidArgumentException",
    "LookupException",
    "NotImplementedException",
    "Stamped",
    "StaticTransformBroadcaster",
    "TimeoutException",
    "TransformBroadcaster",
    "TransformException",
    "TransformListener",
    "TransformRegistration",
    "TransformStamped",
    "TypeException",
    "convert",
]
