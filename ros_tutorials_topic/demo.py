"""The main demo of ``make run`` until the launcher lands: the topic publisher and the
topic subscriber in one process, so messages can be seen flowing. Ctrl-C stops it."""

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor

from ros_tutorials_common import init
from ros_tutorials_topic.publisher import TopicPublisher
from ros_tutorials_topic.subscriber import TopicSubscriber


def main() -> int:
    init()
    executor = SingleThreadedExecutor()
    nodes = [TopicPublisher(), TopicSubscriber()]
    for node in nodes:
        executor.add_node(node)
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        for node in nodes:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
