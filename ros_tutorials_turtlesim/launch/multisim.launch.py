# turtlesim's multisim.launch.py as ROS 2 Jazzy ships it (ros/ros_tutorials, turtlesim/launch):
# two simulators, in the namespaces turtlesim1 and turtlesim2. The Launching-Multiple-Nodes
# tutorial runs it: `ros2 launch turtlesim multisim.launch.py`. (Seed 003's version, with
# mimic joining the two, is multisim.launch and multisim.launch.xml.)

import launch_ros.actions
from launch import LaunchDescription


def generate_launch_description():
    return LaunchDescription(
        [
            launch_ros.actions.Node(
                namespace="turtlesim1",
                package="turtlesim",
                executable="turtlesim_node",
                output="screen",
            ),
            launch_ros.actions.Node(
                namespace="turtlesim2",
                package="turtlesim",
                executable="turtlesim_node",
                output="screen",
            ),
        ]
    )
