"""The topic lesson: publisher and subscriber in-process, and as real processes."""

from __future__ import annotations

from helpers import run, spin_until
from rclpy.node import Node
from ros_tutorials_interfaces.msg import MsgTutorial
from std_msgs.msg import String

from ros_tutorials_topic.listener import Listener
from ros_tutorials_topic.publisher import TopicPublisher
from ros_tutorials_topic.subscriber import TopicSubscriber
from ros_tutorials_topic.talker import Talker


def test_publisher_sends_counting_stamped_messages(context, executor):
    publisher = TopicPublisher(context=context)
    probe = Node("probe", context=context)
    received: list[MsgTutorial] = []
    probe.create_subscription(MsgTutorial, "ros_tutorial_msg", received.append, 100)
    for node in (publisher, probe):
        executor.add_node(node)

    spin_until(executor, lambda: len(received) >= 5, what="5 messages on ros_tutorial_msg")

    assert all(isinstance(msg, MsgTutorial) for msg in received)
    data = [msg.data for msg in received]
    # Late joiners may miss the first few, but what arrives counts up by one.
    assert data == list(range(data[0], data[0] + len(data)))
    stamps = [msg.stamp.sec * 10**9 + msg.stamp.nanosec for msg in received]
    assert stamps == sorted(stamps) and len(set(stamps)) == len(stamps)
    now = publisher.get_clock().now().nanoseconds
    assert 0 < now - stamps[-1] < 60 * 10**9, "stamp is not the current time"


def test_subscriber_logs_what_it_receives(context, executor, capfd):
    subscriber = TopicSubscriber(context=context)
    probe = Node("probe", context=context)
    pub = probe.create_publisher(MsgTutorial, "ros_tutorial_msg", 100)
    for node in (subscriber, probe):
        executor.add_node(node)
    log = ""

    def publish_and_check() -> bool:
        nonlocal log
        pub.publish(MsgTutorial(data=42))
        log += capfd.readouterr().err
        return "recieve msg = 42" in log

    spin_until(executor, publish_and_check, what="the subscriber to log 'recieve msg = 42'")
    assert "[topic_subscriber]: recieve msg = 42" in log


def test_talker_and_listener_say_hello_world(context, executor):
    talker = Talker(context=context)
    listener = Listener(context=context)
    heard: list[str] = []
    listener.create_subscription(String, "chatter", lambda msg: heard.append(msg.data), 10)
    for node in (talker, listener):
        executor.add_node(node)

    spin_until(executor, lambda: len(heard) >= 3, what="3 messages on chatter")
    first = int(heard[0].removeprefix("hello world "))
    assert heard[:3] == [f"hello world {first + i}" for i in range(3)]


def test_publisher_and_subscriber_processes_talk(node_process):
    subscriber = node_process("-m", "ros_tutorials_topic.subscriber")
    publisher = node_process("-m", "ros_tutorials_topic.publisher")

    lines = subscriber.wait_for_output(
        lambda lines: sum("recieve msg = " in line for line in lines) >= 9,
        what="three received messages",
    )
    received = [line for line in lines if "[topic_subscriber]: recieve msg = " in line]
    data = [int(line.rsplit("= ", 1)[1]) for line in received[2::3]]
    assert data == list(range(data[0], data[0] + len(data)))

    assert publisher.interrupt() == 0
    assert subscriber.interrupt() == 0
    for proc in (publisher, subscriber):
        assert "Traceback" not in proc.output


def test_nodes_take_standard_ros_arguments(node_process, context, executor):
    publisher = node_process(
        "-m",
        "ros_tutorials_topic.publisher",
        "--ros-args",
        "-r",
        "__node:=renamed",
        "-r",
        "__ns:=/demo",
        "-r",
        "ros_tutorial_msg:=other_topic",
    )
    probe = Node("probe", context=context)
    received: list[MsgTutorial] = []
    probe.create_subscription(MsgTutorial, "/demo/other_topic", received.append, 100)
    executor.add_node(probe)
    spin_until(executor, lambda: bool(received), what="a message on /demo/other_topic")
    # Node names travel separately from the data (ros_discovery_info): wait for them too.
    spin_until(
        executor,
        lambda: ("renamed", "/demo") in probe.get_node_names_and_namespaces(),
        what="node /demo/renamed in the ROS graph",
    )
    assert publisher.interrupt() == 0


def test_malformed_ros_arguments_give_rcls_error_and_ros2_run_one_line(node_process):
    # The lesson is plain rclpy: rcl's own error and rclpy.init's traceback, as any ROS 2 node.
    proc = node_process("-m", "ros_tutorials_topic.publisher", "--ros-args", "-r", "bad")
    assert proc.wait() != 0
    assert "Couldn't parse remap rule: '-r bad'" in proc.output
    # `ros2 run` checks the ROS arguments before it starts the node: one line.
    result = run("ros2", "run", "ros_tutorials_topic", "topic_publisher", "--ros-args", "-r", "bad")
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr.startswith("error: invalid ROS arguments: ")
    assert result.stderr.count("\n") == 1, result.stderr
