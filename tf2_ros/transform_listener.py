"""tf2_ros.TransformListener: fills a Buffer from the /tf and /tf_static topics.

Subscribes with tf2's QoS: /tf keep-last 100, volatile; /tf_static keep-last 100, transient
local (so a late listener still gets every latched static transform). Its callbacks are in a
reentrant group, so a lookup with a timeout in another callback of the node can be answered
while it waits (with a multi-threaded executor).

``spin_thread=True`` gives the listener a thread of its own, as rclcpp's TransformListener
has (by default: the tf2 pages are C++): that thread alone takes /tf and /tf_static, so a
lookup with a timeout in a callback of the node sees the transforms that arrive while it
waits, whatever executor runs the node; and while no executor runs the node (a program that
does not spin), the thread runs the node's other callbacks too, as tf2_ros's Python listener
does. (rclpy's executors take a node whole; the listener's thread takes its subscriptions
without taking the node, and the node's own executor leaves them to it.)
The thread ends when ROS shuts down or the listener goes (``stop_spinning``).
"""

from __future__ import annotations

import threading
from threading import Thread
from typing import Any

from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from tf2_msgs.msg import TFMessage

from ros_tutorials_common.ros import SpinThread
from tf2_ros.buffer import Buffer

__all__ = ["TransformListener"]

AUTHORITY = "default_authority"  # what tf2_ros's listener records as each frame's broadcaster


# How often the listener's thread looks again at what the node has (a node nobody spins
# gains a client or a timer without waking it).
REFRESH_PERIOD = 0.25


class _ListenerGroup(ReentrantCallbackGroup):
    """The listener's subscriptions: with a thread of its own, only that thread takes them."""

    def __init__(self) -> None:
        super().__init__()
        self.thread: Thread | None = None

    def can_execute(self, entity: object) -> bool:
        return self.thread is None or threading.current_thread() is self.thread


class _ListenerExecutor(SingleThreadedExecutor):
    """Runs the listener's callbacks, and the node's others while no executor has the node;
    never takes the node from the executor the program adds it to."""

    def __init__(self, node: Node, group: _ListenerGroup) -> None:
        super().__init__(context=node.context)
        self._node = node
        self._group = group

    def get_nodes(self) -> list[Node]:
        return [self._node]

    def can_execute(self, entity: Any) -> bool:
        mine = entity.callback_group is self._group
        return (mine or self._node.executor is None) and super().can_execute(entity)

    def spin_once(self, timeout_sec: float | None = None) -> None:
        super().spin_once(REFRESH_PERIOD if timeout_sec is None else timeout_sec)


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
        self.group = _ListenerGroup()
        self.tf_sub = node.create_subscription(
            TFMessage, "/tf", self.callback, qos, callback_group=self.group
        )
        self.tf_static_sub = node.create_subscription(
            TFMessage, "/tf_static", self.static_callback, static_qos, callback_group=self.group
        )
        if spin_thread:  # as tf2_ros: its executor and thread, by these names
            self.spinner = SpinThread(
                node, name="tf2_listener", executor=_ListenerExecutor(node, self.group)
            )
            self.executor = self.spinner.executor
            self.dedicated_listener_thread = self.spinner.thread
            self.group.thread = self.dedicated_listener_thread

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
        self._set(data, False)

    def static_callback(self, data: TFMessage) -> None:
        self._set(data, True)

    def _set(self, data: TFMessage, is_static: bool) -> None:
        set_transforms = getattr(self.buffer, "set_transforms", None)
        if set_transforms is not None:  # tf2_ros.Buffer: the message's transforms at once
            set_transforms(data.transforms, AUTHORITY, is_static)
            return
        add = self.buffer.set_transform_static if is_static else self.buffer.set_transform
        for transform in data.transforms:
            add(transform, AUTHORITY)
