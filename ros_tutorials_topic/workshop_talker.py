"""Talker of seed 004 (the "ROS Overview" workshop's rospy talker.py), in rclpy.

Publishes std_msgs/String "hello world" on ``chatter`` ten times a second and logs each.

    ros2 run ros_tutorials_topic workshop_talker     (or, as the seed: rosrun my_package talker.py)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        # rospy.init_node('talker'); the logger services let rqt_logger_level set its level
        super().__init__("talker", enable_logger_service=True)
        self.pub = self.create_publisher(String, "chatter", 10)  # queue_size=10
        self.timer = self.create_timer(0.1, self.talk)  # rospy.Rate(10): ten times a second

    def talk(self):
        hello_str = "hello world"
        self.get_logger().info(hello_str)  # rospy.loginfo(hello_str)
        self.pub.publish(String(data=hello_str))


def main(args=None):
    rclpy.init(args=args)
    node = Talker()
    try:
        rclpy.spin(node)  # the seed's `while not rospy.is_shutdown()` loop, run by the timer
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C: the seed's `except rospy.ROSInterruptException: pass`
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
