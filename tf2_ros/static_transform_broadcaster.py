"""tf2_ros.StaticTransformBroadcaster: latches a node's fixed frames on /tf_static.

Its publisher is keep-last 1, transient local: the one message holding every static transform
the node has sent is kept for subscribers that come later. A transform for a child frame sent
before replaces the old one, so the message holds one transform per child frame.
"""

from __future__ import annotations

from collections.abc import Iterable

from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from tf2_msgs.msg import TFMessage

__all__ = ["StaticTransformBroadcaster"]


class StaticTransformBroadcaster:
    """Publishes, latched, all the static transforms sent through it."""

    def __init__(self, node: Node, qos: QoSProfile | int | None = None) -> None:
        if qos is None:
            qos = QoSProfile(
                depth=1,
                durability=DurabilityPolicy.TRANSIENT_LOCAL,
                history=HistoryPolicy.KEEP_LAST,
            )
        self.pub_tf = node.create_publisher(TFMessage, "/tf_static", qos)
        self.net_message = TFMessage()
        self._by_child: dict[str, int] = {}

    def sendTransform(self, transform: TransformStamped | Iterable[TransformStamped]) -> None:
        transforms = [transform] if isinstance(transform, TransformStamped) else list(transform)
        for sent in transforms:
            index = self._by_child.get(sent.child_frame_id)
            if index is None:
                self._by_child[sent.child_frame_id] = len(self.net_message.transforms)
                self.net_message.transforms.append(sent)
            else:
                self.net_message.transforms[index] = sent
        self.pub_tf.publish(self.net_message)
