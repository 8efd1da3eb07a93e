"""tf2_ros's Python API with real rclpy nodes in this process: broadcasters and a listener
across nodes (the static one latched for a late listener), lookups that wait (a timeout, the
listener's own spin thread, futures), Buffer.transform() of geometry_msgs' stamped types
(tf2_geometry_msgs), the tf2_frames service, and tf2_ros_py's own test cases (test_buffer.py)."""

from __future__ import annotations

import math
import threading
import time

import pytest
import rclpy
from geometry_msgs.msg import (
    Point,
    PointStamped,
    PoseStamped,
    PoseWithCovarianceStamped,
    TransformStamped,
    Vector3Stamped,
)
from helpers import spin_until
from rclpy.duration import Duration
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import DurabilityPolicy
from rclpy.time import Time
from tf2_msgs.srv import FrameGraph

import tf2_geometry_msgs  # noqa: F401 - registers the types Buffer.transform() takes
from tf2_ros import (
    LookupException,
    StaticTransformBroadcaster,
    TransformBroadcaster,
    TransformException,
    TypeException,
)
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener


def transform(parent: str, child: str, stamp: Time, xyz=(0.0, 0.0, 0.0), yaw: float = 0.0):
    message = TransformStamped()
    message.header.frame_id = parent
    message.header.stamp = stamp.to_msg()
    message.child_frame_id = child
    t, r = message.transform.translation, message.transform.rotation
    t.x, t.y, t.z = (float(v) for v in xyz)
    r.z, r.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return message


def node(context, executor, name: str):
    made = rclpy.create_node(name, context=context)
    executor.add_node(made)
    return made


# -- tf2_ros_py/test/test_buffer.py ------------------------------------------------------------


def test_can_transform_a_valid_transform_and_look_it_up():
    buffer = Buffer(cache_time=Duration(seconds=10.0))
    now = rclpy.clock.Clock().now()
    sent = transform("foo", "bar", now, (1, 2, 3))
    assert buffer.set_transform(sent, "unittest") is None
    assert buffer.can_transform("foo", "bar", now)
    output = buffer.lookup_transform("foo", "bar", now)
    assert output.child_frame_id == "bar" and output.transform == sent.transform


def test_awaiting_a_transform_now_and_later():
    buffer = Buffer()
    now = rclpy.clock.Clock().now()
    sent = transform("foo", "bar", now)
    later = buffer.lookup_transform_async("foo", "bar", now)
    later.send(None)  # not there yet: the coroutine waits
    full = buffer.lookup_transform_full_async("foo", now, "bar", now, "foo")
    full.send(None)
    buffer.set_transform(sent, "unittest")
    for coroutine in (later, full):
        with pytest.raises(StopIteration) as done:
            coroutine.send(None)
        assert done.value.value == sent
    at_once = buffer.lookup_transform_async("foo", "bar", now)
    with pytest.raises(StopIteration) as done:
        at_once.send(None)  # already there: no wait at all
    assert done.value.value == sent


def test_a_wait_given_up_is_forgotten():
    # A program that cancels its waits (one per timer tick) must not leave a callback per wait
    # that every new transform runs, for ever.
    buffer = Buffer()
    for _ in range(3):
        buffer.wait_for_transform_async("world", "turtle9", Time()).cancel()
    assert buffer._new_data_callbacks == []
    buffer.set_transform(transform("world", "turtle1", Time(seconds=5)), "test")
    assert buffer._new_data_callbacks == []


def test_lookup_with_a_timeout_waits_then_raises_tf2s_error():
    buffer = Buffer()
    started = time.monotonic()
    with pytest.raises(LookupException) as error:
        buffer.lookup_transform("turtle2", "turtle1", Time(), timeout=Duration(seconds=0.3))
    assert time.monotonic() - started >= 0.3
    assert str(error.value) == (
        '"turtle2" passed to lookupTransform argument target_frame does not exist. '
    )
    assert buffer.can_transform("turtle2", "turtle1", Time(), return_debug_tuple=True) == (
        False,
        'Invalid frame ID "turtle2" passed to canTransform argument target_frame - frame does '
        "not exist",
    )


def test_a_waiting_lookup_is_woken_by_new_data():
    buffer = Buffer()
    sender = threading.Timer(
        0.2, buffer.set_transform, (transform("world", "turtle1", Time(seconds=5)), "test")
    )
    sender.start()
    try:
        looked = buffer.lookup_transform("world", "turtle1", Time(), Duration(seconds=30))
    finally:
        sender.join()
    assert looked.header.stamp == Time(seconds=5).to_msg()


# -- across nodes ------------------------------------------------------------------------------


def test_a_static_transform_reaches_a_listener_that_comes_later(context, executor):
    broadcaster_node = node(context, executor, "static_broadcaster")
    broadcaster = StaticTransformBroadcaster(broadcaster_node)
    assert broadcaster.pub_tf.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL
    assert broadcaster.pub_tf.qos_profile.depth == 1
    broadcaster.sendTransform(transform("world", "mystaticturtle", Time(), (0, 0, 1)))
    broadcaster.sendTransform(transform("world", "other", Time(), (2, 0, 0)))
    broadcaster.sendTransform(transform("world", "mystaticturtle", Time(), (0, 0, 2)))
    assert len(broadcaster.net_message.transforms) == 2  # one per child frame
    listener_node = node(context, executor, "listener")
    buffer = Buffer()
    TransformListener(buffer, listener_node)
    spin_until(
        executor,
        lambda: (
            buffer.can_transform("world", "mystaticturtle", Time())
            and buffer.can_transform("world", "other", Time())
        ),
        what="the latched static transforms",
    )
    looked = buffer.lookup_transform("world", "mystaticturtle", Time())
    assert looked.transform.translation.z == 2.0


def test_a_dynamic_broadcaster_and_a_listener(context, executor):
    broadcaster_node = node(context, executor, "turtle1_broadcaster")
    broadcaster = TransformBroadcaster(broadcaster_node)
    listener_node = node(context, executor, "turtle_listener")
    buffer = Buffer()
    listener = TransformListener(buffer, listener_node)
    assert listener.tf_sub.qos_profile.depth == 100
    assert listener.tf_static_sub.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL
    stamps = [Time(seconds=100), Time(seconds=101)]

    def sent_and_heard() -> bool:
        broadcaster.sendTransform([transform("world", "turtle1", s, (s.nanoseconds / 1e9, 0, 0))
                                   for s in stamps])  # fmt: skip
        return buffer.can_transform("world", "turtle1", Time(seconds=100.5))

    spin_until(executor, sent_and_heard, what="turtle1 on /tf")
    looked = buffer.lookup_transform("world", "turtle1", Time(seconds=100.5))
    assert looked.transform.translation.x == pytest.approx(100.5)
    assert buffer.get_latest_common_time("world", "turtle1") == Time(seconds=101)


class TimerLookupListener(rclpy.node.Node):
    """The Time and Debugging pages' listener: a lookup at now() with a 50 ms timeout in a
    timer callback of a node that rclpy.spin() runs (the pages' turtle_tf2 listener)."""

    def __init__(self, context, spin_thread: bool) -> None:
        super().__init__("turtle_tf2_frame_listener", context=context)
        self.tf_buffer = Buffer()
        self.tf_listener = TransformListener(self.tf_buffer, self, spin_thread=spin_thread)
        self.found: list = []
        self.failures: list[str] = []
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self) -> None:
        try:
            t = self.tf_buffer.lookup_transform(
                "turtle2", "turtle1", self.get_clock().now(), timeout=Duration(seconds=0.05)
            )
        except TransformException as ex:
            self.failures.append(str(ex))
            return
        self.found.append(t)


def test_a_lookup_at_now_with_a_timeout_in_a_timer_callback_sees_new_data(context, executor):
    """With spin_thread=True the listener's own thread fills the buffer while the timer
    callback waits (rclcpp's listener, the pages' C++, always has that thread): the lookup at
    now() succeeds once the broadcaster's next transforms arrive. (Before: the node's one
    executor was blocked in the callback, so every lookup was an extrapolation into the
    future.)"""
    broadcaster_node = rclpy.create_node("turtle_broadcasters", context=context)
    broadcaster = TransformBroadcaster(broadcaster_node)

    def broadcast() -> None:
        now = broadcaster_node.get_clock().now()
        broadcaster.sendTransform(
            [
                transform("world", "turtle1", now, (5, 5, 0)),
                transform("world", "turtle2", now, (4, 2, 0)),
            ]
        )

    broadcaster_node.create_timer(0.02, broadcast)
    broadcasting = SingleThreadedExecutor(context=context)
    broadcasting.add_node(broadcaster_node)
    threading.Thread(target=broadcasting.spin, daemon=True).start()
    listener = TimerLookupListener(context, spin_thread=True)
    executor.add_node(listener)  # rclpy.spin(node): the node's timer runs here
    try:
        spin_until(executor, lambda: len(listener.found) >= 3, what="three lookups at now()")
        looked = listener.found[-1].transform.translation
        assert (looked.x, looked.y) == (pytest.approx(1.0), pytest.approx(3.0))
    finally:
        listener.tf_listener.executor.shutdown()
        broadcasting.shutdown()
        broadcaster_node.destroy_node()


def test_the_listeners_spin_thread_answers_a_lookup_of_a_program_that_does_not_spin(context):
    broadcaster_node = rclpy.create_node("static_for_thread", context=context)
    listener_node = rclpy.create_node("thread_listener", context=context)
    try:
        StaticTransformBroadcaster(broadcaster_node).sendTransform(
            transform("base", "laser", Time(), (0.1, 0, 0.2))
        )
        other = SingleThreadedExecutor(context=context)
        other.add_node(broadcaster_node)
        spinning = threading.Thread(target=other.spin, daemon=True)
        spinning.start()
        buffer = Buffer()
        listener = TransformListener(buffer, listener_node, spin_thread=True)
        # No spin here: the listener's own thread receives the transform while this waits.
        looked = buffer.lookup_transform("base", "laser", Time(), timeout=Duration(seconds=30))
        assert looked.transform.translation.z == pytest.approx(0.2)
        listener.executor.shutdown()
        other.shutdown()
    finally:
        listener_node.destroy_node()
        broadcaster_node.destroy_node()


def test_the_tf2_frames_service_answers_the_frames_as_yaml(context, executor):
    server = node(context, executor, "buffer_node")
    buffer = Buffer(node=server)
    buffer.set_transform(transform("world", "turtle1", Time(seconds=3)), "default_authority")
    client_node = node(context, executor, "frames_client")
    client = client_node.create_client(FrameGraph, "tf2_frames")
    spin_until(executor, client.service_is_ready, what="the tf2_frames service")
    future = client.call_async(FrameGraph.Request())
    spin_until(executor, future.done, what="the tf2_frames answer")
    assert future.result().frame_yaml.startswith("turtle1: \n  parent: 'world'\n")


# -- Buffer.transform() and tf2_geometry_msgs --------------------------------------------------


def buffer_with_a_turned_frame() -> Buffer:
    """map -> odom: 1 m along x and turned 90 degrees about z, at 10 s."""
    buffer = Buffer()
    buffer.set_transform(transform("map", "odom", Time(seconds=10), (1, 0, 0), math.pi / 2), "t")
    return buffer


def test_transform_a_point_a_vector_and_poses():
    buffer = buffer_with_a_turned_frame()
    point = PointStamped()
    point.header.frame_id, point.header.stamp = "odom", Time(seconds=10).to_msg()
    point.point.x, point.point.y = 2.0, 0.0
    moved = buffer.transform(point, "map")
    assert (moved.point.x, moved.point.y, moved.point.z) == pytest.approx((1, 2, 0))
    assert moved.header.frame_id == "map"
    vector = Vector3Stamped(header=point.header)
    vector.vector.x = 2.0
    turned = buffer.transform(vector, "map")  # a direction: turned, not moved
    assert (turned.vector.x, turned.vector.y) == pytest.approx((0, 2))
    pose = PoseStamped(header=point.header)
    pose.pose.position.x = 2.0
    pose.pose.orientation.w = 1.0
    placed = buffer.transform(pose, "map").pose
    assert (placed.position.x, placed.position.y) == pytest.approx((1, 2))
    q = placed.orientation
    assert (q.x, q.y, q.z, q.w) == pytest.approx(
        (0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4))
    )
    covariant = PoseWithCovarianceStamped(header=point.header)
    covariant.pose.pose.orientation.w = 1.0
    covariant.pose.covariance[0] = 4.0  # variance along odom's x
    rotated = buffer.transform(covariant, "map").pose.covariance
    assert rotated[0] == pytest.approx(0) and rotated[7] == pytest.approx(4)  # now along y
    laser = TransformStamped(header=point.header, child_frame_id="laser")
    laser.transform.translation.x = 2.0
    laser.transform.rotation.w = 1.0
    chained = buffer.transform(laser, "map")
    assert chained.child_frame_id == "laser" and chained.header.frame_id == "map"
    assert (chained.transform.translation.x, chained.transform.translation.y) == pytest.approx(
        (1, 2)
    )


def test_transform_of_an_unknown_type_or_an_unknown_time():
    buffer = buffer_with_a_turned_frame()
    with pytest.raises(TypeException, match="is not loaded or supported"):
        buffer.transform(Point(), "map")
    point = PointStamped()
    point.header.frame_id, point.header.stamp = "odom", Time(seconds=30).to_msg()
    with pytest.raises(TransformException, match="extrapolation"):
        buffer.transform(point, "map")


def test_bad_transforms_on_tf_are_refused_and_the_listener_goes_on(context, executor, capfd):
    broadcaster = TransformBroadcaster(node(context, executor, "bad_broadcaster"))
    buffer = Buffer()
    TransformListener(buffer, node(context, executor, "patient_listener"))
    loop = [transform("x", "y", Time(seconds=1)), transform("y", "x", Time(seconds=1))]
    nan = transform("world", "broken", Time(seconds=1), (math.nan, 0, 0))
    good = transform("world", "fine", Time(seconds=1), (1, 0, 0))

    def heard() -> bool:
        broadcaster.sendTransform([*loop, nan, good])
        return buffer.can_transform("world", "fine", Time())

    spin_until(executor, heard, what="the good transform after the bad ones")
    assert not buffer.can_transform("world", "broken", Time())
    possible, message = buffer.can_transform("x", "world", Time(), return_debug_tuple=True)
    assert not possible
    assert message.startswith("The tf tree is invalid because it contains a loop.\n")
    with pytest.raises(LookupException, match="contains a loop"):
        buffer.lookup_transform("fine", "x", Time(seconds=1))
    assert 'TF_NAN_INPUT: Ignoring transform for child_frame_id "broken"' in capfd.readouterr().err


def test_transform_stamped_comes_from_tf2_ros_as_in_jazzy():
    """`from tf2_ros import TransformBroadcaster, TransformStamped`: the URDF page's
    state_publisher.py imports geometry_msgs' message through tf2_ros, as Jazzy's star
    imports hand it on."""
    import tf2_ros

    assert tf2_ros.TransformStamped is TransformStamped
    assert "TransformStamped" in tf2_ros.__all__
