"""tf2_ros.TransformListener: fills a Buffer from the /tf and /tf_static topics.

Subscribes with tf2's QoS: /tf keep-last 100, volatile; /tf_static keep-last 100, transient
local (so a late listener still gets every latched static transform). Its callbacks are in a
reentrant group, so a lookup with a timeout in another callback of the node can be answered
while it waits (with a multi-threaded executor). ``spin_thread=True`` spins the node in a
thread of the listener's own, as tf2_ros does, so a lookup with a timeout works in a program
that does not spin; the thread ends when ROS shuts down or the listener goes (``stop_spinning``).
"""

from __future__ import annotations

from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from tf2_msgs.msg import TFMessage

from ros_tutorials_common.ros import SpinThread
from tf2_ros.buffer import Buffer

__all__ = ["TransformListener"]

AUTHORITY = "default_authority"  # what tf2_ros's listener records as each frame's broadcaster


class TransformListener:
    """Feeds BUFFER with what NODE receives on /tf and /tf_static."""

    def __init__(
        self,
        buffer: Buffer,
        node: Node,
        *,
        spin_thread: bool = False,
        qos: QoSProfile | int | None = None,
        static_qos: QoSProfile | int | None = None,
    ) -> None:
        if qos is None:
            qos = QoSProfile(
                depth=100, durability=DurabilityPolicy.VOLATILE, history=HistoryPolicy.KEEP_LAST
            )
        if static_qos is None:
            static_qos = QoSProfile(
                depth=100,
                durability=DurabilityPolicy.TRANSIENT_LOCAL,
                history=HistoryPolicy.KEEP_LAST,
            )
        self.buffer = buffer
        self.node = node
        self.group = ReentrantCallbackGroup()
        self.tf_sub = node.create_subscription(
            TFMessage, "/tf", self.callback, qos, callback_group=self.group
        )
        self.tf_static_sub = node.create_subscription(
            TFMessage, "/tf_static", self.static_callback, static_qos, callback_group=self.group
        )
        if spin_thread:  # as tf2_ros: its executor and thread, by these names
            self.spinner = SpinThread(node, name="tf2_listener")
            self.executor = self.spinner.executor
            self.dedicated_listener_thread = self.spinner.thread

    def stop_spinning(self) -> None:
        """End the spin thread, if there is one (before the node is destroyed)."""
        spinner = getattr(self, "spinner", None)
        if spinner is not None:
            spinner.stop()

    def __del__(self) -> None:
        self.stop_spinning()

    def unregister(self) -> None:
        """Stop listening: destroy the two subscriptions."""
        self.node.destroy_subscription(self.tf_sub)
        self.node.destroy_subscription(self.tf_static_sub)

    def callback(self, data: TFMessage) -> None:
        for transform in data.transforms:
            self.buffer.set_transform(transform, AUTHORITY)

    def static_callback(self, data: TFMessage) -> None:
        for transform in data.transforms:
            self.buffer.set_transform_static(transform, AUTHORITY)
