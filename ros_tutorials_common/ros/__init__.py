"""The part of ros_tutorials_common that imports rclpy (the rest of the package never does),
for the tools and turtlesim; the lessons are plain rclpy and use none of it. A tool reads::

    from ros_tutorials_common.ros import init, user_args

    options = parse_args(user_args(argv))   # the program's own arguments
    init(argv)                              # rclpy.init, with the DDS defaults

and ends as ros_tutorials_common/shutdown.py says, its spin's stop told by ``node_stopped``.
"""

from ros_tutorials_common.ros.node_main import (
    NODE_STOPPED,
    RCLError,
    SpinThread,
    ThreadRequests,
    init,
    node_stopped,
    ros_args,
    run_node,
    user_args,
)

__all__ = [
    "NODE_STOPPED",
    "RCLError",
    "SpinThread",
    "ThreadRequests",
    "init",
    "node_stopped",
    "ros_args",
    "run_node",
    "user_args",
]
