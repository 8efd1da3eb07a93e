"""turtle_tf2_message_broadcaster: spawn turtle3, drive it in a circle, publish where it is.

The sensor-message demo of the tf2 page "Using stamped datatypes with tf2_ros::MessageFilter":
turtle3's position as a geometry_msgs/PointStamped in the world frame on
/turtle3/turtle_point_stamped, as an overhead camera would report it.

ros2 launch turtle_tf2_py turtle_tf2_sensor_message.launch.py
"""

import rclpy
from geometry_msgs.msg import PointStamped, Twist
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import Spawn


class PointPublisher(Node):
    def __init__(self):
        super().__init__("turtle_tf2_message_broadcaster")
        # A client to spawn turtle3, and where the spawning is
        self.spawner = self.create_client(Spawn, "spawn")
        self.turtle_spawning_service_ready = False
        self.turtle_spawned = False
        self.turtle_pose_cansubscribe = False
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        if self.turtle_spawning_service_ready:
            if self.turtle_spawned:
                self.turtle_pose_cansubscribe = True
            elif self.result.done():
                self.get_logger().info(f"Successfully spawned {self.result.result().name}")
                self.turtle_spawned = True
            else:
                self.get_logger().info("Spawn is not finished")
        elif self.spawner.service_is_ready():
            # turtle3 at (4, 2), facing along x
            request = Spawn.Request(name="turtle3", x=4.0, y=2.0, theta=0.0)
            self.result = self.spawner.call_async(request)
            self.turtle_spawning_service_ready = True
        else:
            self.get_logger().info("Service is not ready")

        if self.turtle_pose_cansubscribe:
            self.timer.cancel()  # the endpoints are made once
            self.vel_pub = self.create_publisher(Twist, "turtle3/cmd_vel", 10)
            self.sub = self.create_subscription(Pose, "turtle3/pose", self.handle_turtle_pose, 10)
            self.pub = self.create_publisher(PointStamped, "turtle3/turtle_point_stamped", 10)

    def handle_turtle_pose(self, msg):
        # Drive turtle3 in a circle
        vel_msg = Twist()
        vel_msg.linear.x = 1.0
        vel_msg.angular.z = 1.0
        self.vel_pub.publish(vel_msg)
        # Report where it is, in the world frame
        ps = PointStamped()
        ps.header.stamp = self.get_clock().now().to_msg()
        ps.header.frame_id = "world"
        ps.point.x = msg.x
        ps.point.y = msg.y
        ps.point.z = 0.0
        self.pub.publish(ps)


def main() -> None:
    rclpy.init()
    node = PointPublisher()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
