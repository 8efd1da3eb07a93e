"""turtlesim with two turtles: turtle2 follows TARGET_FRAME (turtle1 unless told).

ros2 launch turtle_tf2_py turtle_tf2_demo.launch.py [target_frame:=carrot1]
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
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
            Node(package="turtlesim", executable="turtlesim_node", name="sim"),
            broadcaster("turtle1"),
            broadcaster("turtle2"),
            Node(
                package="turtle_tf2_py",
                executable="turtle_tf2_listener",
                name="listener",
                parameters=[{"target_frame": LaunchConfiguration("target_frame")}],
            ),
        ]
    )
