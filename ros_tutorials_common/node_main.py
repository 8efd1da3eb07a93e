"""How every tutorial executable starts, spins and stops.

A tutorial's main() is one line: ``return run_node(TopicPublisher)``. This helper applies
the DDS defaults, initialises rclpy with the process arguments (so ``--ros-args -r ...
-p ...`` work), spins the node, and turns Ctrl-C or SIGTERM into a clean exit with status 0.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence

import rclpy
from rclpy.exceptions import ParameterException
from rclpy.executors import ExternalShutdownException
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy
from rclpy.node import Node
from rclpy.utilities import remove_ros_args

from ros_tutorials_common.dds import apply_dds_defaults


def user_args(argv: Sequence[str] | None = None) -> list[str]:
    """The command-line arguments meant for the program, without the ROS ones."""
    argv = sys.argv if argv is None else argv
    return remove_ros_args(args=list(argv))[1:]


def init(argv: Sequence[str] | None = None) -> None:
    """Initialise rclpy for an executable, with this project's DDS defaults.

    Malformed ROS arguments (``--ros-args -r bad``) end the program with one clear line
    and a non-zero exit status, not a traceback.
    """
    apply_dds_defaults()
    try:
        rclpy.init(args=list(sys.argv if argv is None else argv))
    except _rclpy.RCLError as error:
        reason = str(error).split(", at ")[0]
        raise SystemExit(f"error: invalid ROS arguments: {reason}") from None


def run_node(make_node: Callable[[], Node], argv: Sequence[str] | None = None) -> int:
    """Create a node, spin it until Ctrl-C or shutdown, then clean up. Returns the exit code.

    A parameter given at start that the node refuses (``-p calculation_method:=7``, or a
    params file with a wrong type) ends the program with one clear line, not a traceback.
    """
    init(argv)
    node = None
    try:
        node = make_node()
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    except ParameterException as error:
        raise SystemExit(f"error: {error}") from None
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0
