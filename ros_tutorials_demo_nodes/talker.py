"""The official tutorials' talker (ros2/demos, Jazzy: demo_nodes_cpp's talker), in Python.

Publishes std_msgs/String "Hello World: N" (N from 1) on ``chatter`` once a second, logging
each as demo_nodes_cpp does. The pages that use it (Using ros2doctor, the launch system,
recording a bag, ...) type:

    ros2 run demo_nodes_cpp talker

The course's own talker (``ros2 run ros_tutorials_topic talker``) is the ROS 1 book's: "hello
world N" ten times a second.
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile
from std_msgs.msg import String


class Talker(Node):
    def __init__(self) -> None:
        super().__init__("talker")
        self.count = 1
        self.publisher = self.create_publisher(String, "chatter", QoSProfile(depth=7))
        self.timer = self.create_timer(1.0, self.publish_message)

    def publish_message(self) -> None:
        msg = String(data=f"Hello World: {self.count}")
        self.count += 1
        self.get_logger().info(f"Publishing: '{msg.data}'")
        self.publisher.publish(msg)


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = Talker()  # create the node
    try:
        rclpy.spin(node)  # publish once a second until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    except RuntimeError:  # the timer published just as Ctrl-C shut ROS down (rclpy's race)
        if rclpy.ok():
            raise  # any other error is one
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
