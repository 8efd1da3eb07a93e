"""The part of ros_tutorials_common that imports rclpy (the rest of the package never does).

A lesson's main() reads::

    from ros_tutorials_common.ros import ros_args, user_args

    options = parse_args(user_args(args))   # the program's own arguments (clients only)
    rclpy.init(args=ros_args(args))
"""

from ros_tutorials_common.ros.node_main import RCLError, init, ros_args, run_node, user_args

__all__ = ["RCLError", "init", "ros_args", "run_node", "user_args"]
