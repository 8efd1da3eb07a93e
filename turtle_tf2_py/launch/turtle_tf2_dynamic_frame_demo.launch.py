"""The demo with the moving frame carrot1 around turtle1; turtle2 follows the carrot.

ros2 launch turtle_tf2_py turtle_tf2_dynamic_frame_demo.launch.py
"""

import os

from ament_index_python.packages import get_package_share_directory

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    demo = os.path.join(
        get_package_share_directory("turtle_tf2_py"), "launch", "turtle_tf2_demo.launch.py"
    )
    return LaunchDescription(
        [
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(demo),
                launch_arguments={"target_frame": "carrot1"}.items(),
            ),
            Node(
                package="turtle_tf2_py",
                executable="dynamic_frame_tf2_broadcaster",
                name="dynamic_broadcaster",
            ),
        ]
    )
