"""turtle_tf2_listener: spawn turtle2 and steer it towards TARGET_FRAME (turtle1 by default),
looking up where the target is in turtle2's frame once a second.

    ros2 run turtle_tf2_py turtle_tf2_listener --ros-args -p target_frame:=carrot1
"""

import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.time import Time
from turtlesim.srv import Spawn

from tf2_ros import TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener


class FrameListener(Node):
    def __init__(self):
        super().__init__("turtle_tf2_frame_listener")
        self.target_frame = self.declare_parameter("target_frame", "turtle1").value

        # The listener fills the buffer from /tf and /tf_static
        self.tf_buffer = Buffer()
        self.tf_listener = TransformListener(self.tf_buffer, self)

        self.spawner = self.create_client(Spawn, "spawn")
        self.spawn_future = None  # set once the spawn request is sent
        self.turtle_spawned = False

        self.publisher = self.create_publisher(Twist, "turtle2/cmd_vel", 1)
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        if self.spawn_future is None:
            self.spawn_turtle2()
        elif not self.turtle_spawned:
            if self.spawn_future.done():
                self.get_logger().info(f"Successfully spawned {self.spawn_future.result().name}")
                self.turtle_spawned = True
            else:
                self.get_logger().info("Spawn is not finished")
        else:
            self.follow()

    def spawn_turtle2(self):
        if not self.spawner.service_is_ready():
            self.get_logger().info("Service is not ready")
            return
        request = Spawn.Request(x=4.0, y=2.0, theta=0.0, name="turtle2")
        self.spawn_future = self.spawner.call_async(request)

    def follow(self):
        # Where the target is, seen from turtle2; Time() asks for the latest transform
        try:
            t = self.tf_buffer.lookup_transform("turtle2", self.target_frame, Time())
        except TransformException as ex:
            self.get_logger().info(f"Could not transform turtle2 to {self.target_frame}: {ex}")
            return
        x, y = t.transform.translation.x, t.transform.translation.y
        msg = Twist()
        msg.angular.z = 1.0 * math.atan2(y, x)  # turn towards it
        msg.linear.x = 0.5 * math.hypot(x, y)  # faster the farther it is
        self.publisher.publish(msg)


def main() -> None:
    rclpy.init()
    node = FrameListener()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
