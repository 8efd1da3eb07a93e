"""A package's robot in the 3D view: robot_state_publisher, the joints' publisher, rviz2.

ros2 launch urdf_launch display.launch.py urdf_package:=PKG urdf_package_path:=urdf/X.urdf
    [jsp_gui:=false] [rviz_config:=/path/to/file.rviz]
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    urdf_launch_package = FindPackageShare("urdf_launch")
    default_rviz_config_path = PathJoinSubstitution([urdf_launch_package, "config", "urdf.rviz"])
    return LaunchDescription(
        [
            DeclareLaunchArgument(
                name="jsp_gui",
                default_value="true",
                choices=["true", "false"],
                description="Flag to enable joint_state_publisher_gui",
            ),
            DeclareLaunchArgument(
                name="rviz_config",
                default_value=default_rviz_config_path,
                description="Absolute path to rviz config file",
            ),
            IncludeLaunchDescription(
                PathJoinSubstitution([urdf_launch_package, "launch", "description.launch.py"]),
                launch_arguments={
                    "urdf_package": LaunchConfiguration("urdf_package"),
                    "urdf_package_path": LaunchConfiguration("urdf_package_path"),
                }.items(),
            ),
            Node(
                package="joint_state_publisher",
                executable="joint_state_publisher",
                condition=UnlessCondition(LaunchConfiguration("jsp_gui")),
            ),
            Node(
                package="joint_state_publisher_gui",
                executable="joint_state_publisher_gui",
                condition=IfCondition(LaunchConfiguration("jsp_gui")),
            ),
            Node(
                package="rviz2",
                executable="rviz2",
                output="screen",
                arguments=["-d", LaunchConfiguration("rviz_config")],
            ),
        ]
    )
