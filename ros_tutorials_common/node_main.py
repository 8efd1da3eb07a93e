"""How every tutorial executable starts, spins and stops.

A tutorial's main() is one line: ``return run_node(TopicPublisher)``. This helper applies
the DDS defaults, initialises rclpy with the process arguments (so ``--ros-args -r ...
-p ...`` work), spins the node, and turns Ctrl-C or SIGTERM into a clean exit with status 0.
A node whose callbacks must run at the same time (an action server that sees a cancel while
it executes a goal) passes ``make_executor=``, e.g. a MultiThreadedExecutor factory.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence

import rclpy
from rclpy.exceptions import ParameterException
from rclpy.executors import Executor, ExternalShutdownException
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from rclpy.utilities import remove_ros_args

from ros_tutorials_common.dds import apply_dds_defaults


def user_args(argv: Sequence[str] | None = None) -> list[str]:
    """The command-line arguments meant for the program, without the ROS ones.

    Malformed ROS arguments end the program here already, with one clear line.
    """
    argv = sys.argv if argv is None else argv
    try:
        return remove_ros_args(args=list(argv))[1:]
    except _rclpy.RCLError as error:
        raise _invalid_ros_arguments(error) from None


def init(
    argv: Sequence[str] | None = None,
    signal_handler_options: SignalHandlerOptions | None = None,
) -> None:
    """Initialise rclpy for an executable, with this project's DDS defaults.

    Malformed ROS arguments (``--ros-args -r bad``) end the program with one clear line
    and a non-zero exit status, not a traceback. ``signal_handler_options`` is rclpy's: by
    default its handlers shut ROS down on Ctrl-C/SIGTERM; a program that still needs ROS
    after Ctrl-C (to cancel an action goal) passes ``SignalHandlerOptions.NO``.
    """
    apply_dds_defaults()
    try:
        rclpy.init(
            args=list(sys.argv if argv is None else argv),
            signal_handler_options=signal_handler_options,
        )
    except _rclpy.RCLError as error:
        raise _invalid_ros_arguments(error) from None


def _invalid_ros_arguments(error: Exception) -> SystemExit:
    reason = str(error).split(", at ")[0]  # rcl appends its source file and line
    return SystemExit(f"error: invalid ROS arguments: {reason}")


def run_node(
    make_node: Callable[[], Node],
    argv: Sequence[str] | None = None,
    make_executor: Callable[[], Executor] | None = None,
) -> int:
    """Create a node, spin it until Ctrl-C or shutdown, then clean up. Returns the exit code.

    The executor is rclpy's default (single-threaded) unless ``make_executor`` builds one;
    it is called after rclpy.init, since an executor belongs to an initialised context.

    A parameter given at start that the node refuses (``-p calculation_method:=7``, or a
    params file with a wrong type) ends the program with one clear line, not a traceback.
    """
    init(argv)
    node = None
    executor = None
    try:
        node = make_node()
        executor = make_executor() if make_executor is not None else None
        rclpy.spin(node, executor)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    except ParameterException as error:
        raise SystemExit(f"error: {error}") from None
    finally:
        # The node first: it may have work running in the executor's threads to stop.
        if node is not None:
            node.destroy_node()
        if executor is not None:
            executor.shutdown()
        rclpy.try_shutdown()
    return 0
