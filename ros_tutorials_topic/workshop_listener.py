"""Listener of seed 004 (the "ROS Overview" workshop's rospy listener.py), in rclpy.

Subscribes to ``chatter`` (std_msgs/String) and logs the node's name followed by
"Receive : " and the text, as the seed's ``rospy.get_caller_id() + "Receive : %s"`` does.

    ros2 run ros_tutorials_topic workshop_listener  (as the seed: rosrun my_package listener.py)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String


class Listener(Node):
    def __init__(self):
        super().__init__("listener")  # rospy.init_node('listener')
        self.sub = self.create_subscription(String, "chatter", self.callback, 10)

    def callback(self, data):
        # rospy.get_caller_id() is the node's full name, e.g. /listener
        caller_id = self.get_fully_qualified_name()
        self.get_logger().info(f"{caller_id}Receive : {data.data}")


def main(args=None):
    rclpy.init(args=args)
    node = Listener()
    try:
        rclpy.spin(node)  # rospy.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
