"""turtlesim, turtle1 and turtle3 as tf2 frames, and turtle3's position as PointStamped.

ros2 launch turtle_tf2_py turtle_tf2_sensor_message.launch.py
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node


def generate_launch_description():
    def broadcaster(turtle):
        return Node(
            package="turtle_tf2_py",
            executable="turtle_tf2_broadcaster",
            name="broadcaster" + turtle[-1],
            parameters=[{"turtlename": turtle}],
        )

    return LaunchDescription(
        [
            DeclareLaunchArgument(
                "target_frame", default_value="turtle1", description="Target frame name."
            ),
            Node(package="turtlesim", executable="turtlesim_node", name="sim", output="screen"),
            broadcaster("turtle1"),
            broadcaster("turtle3"),
            Node(
                package="turtle_tf2_py",
                executable="turtle_tf2_message_broadcaster",
                name="message_broadcaster",
            ),
        ]
    )
