"""The URDF pages' viewer: a model of this package in the 3D view, with joint sliders.

ros2 launch urdf_tutorial display.launch.py model:=urdf/06-flexible.urdf [gui:=false]
    [rvizconfig:=/path/to/file.rviz]

``model`` is a path inside this package (a .urdf, or a .xacro: every model goes through
xacro). urdf_launch's display.launch.py does the work: robot_state_publisher with the model,
joint_state_publisher_gui (or joint_state_publisher with gui:=false), and rviz2.
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    urdf_tutorial_path = FindPackageShare("urdf_tutorial")
    default_model_path = PathJoinSubstitution(["urdf", "01-myfirst.urdf"])
    default_rviz_config_path = PathJoinSubstitution([urdf_tutorial_path, "rviz", "urdf.rviz"])
    return LaunchDescription(
        [
            DeclareLaunchArgument(
                name="gui",
                default_value="true",
                choices=["true", "false"],
                description="Flag to enable joint_state_publisher_gui",
            ),
            DeclareLaunchArgument(
                name="rvizconfig",
                default_value=default_rviz_config_path,
                description="Absolute path to rviz config file",
            ),
            DeclareLaunchArgument(
                name="model",
                default_value=default_model_path,
                description="Path to robot urdf file relative to urdf_tutorial package",
            ),
            IncludeLaunchDescription(
                PathJoinSubstitution(
                    [FindPackageShare("urdf_launch"), "launch", "display.launch.py"]
                ),
                launch_arguments={
                    "urdf_package": "urdf_tutorial",
                    "urdf_package_path": LaunchConfiguration("model"),
                    "rviz_config": LaunchConfiguration("rvizconfig"),
                    "jsp_gui": LaunchConfiguration("gui"),
                }.items(),
            ),
        ]
    )
