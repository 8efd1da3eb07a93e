"""robot_state_publisher with a package's URDF or xacro file, run through xacro.

ros2 launch urdf_launch description.launch.py urdf_package:=PKG urdf_package_path:=urdf/X.urdf
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    package_dir = FindPackageShare(LaunchConfiguration("urdf_package"))
    urdf_path = PathJoinSubstitution([package_dir, LaunchConfiguration("urdf_package_path")])
    robot_description = ParameterValue(Command(["xacro ", urdf_path]), value_type=str)
    return LaunchDescription(
        [
            DeclareLaunchArgument(
                "urdf_package", description="The package where the robot description is located"
            ),
            DeclareLaunchArgument(
                "urdf_package_path",
                description="The path to the robot description relative to the package root",
            ),
            Node(
                package="robot_state_publisher",
                executable="robot_state_publisher",
                parameters=[{"robot_description": robot_description}],
            ),
        ]
    )
