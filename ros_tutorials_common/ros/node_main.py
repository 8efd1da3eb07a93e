"""The command line of a tool or a turtlesim node, before and around ``rclpy.init`` (the
lessons are plain rclpy: ``ros2 run``, the launcher and the activated environment give them
the DDS defaults)::

    options = parse_args(user_args(argv))   # the program's own arguments
    init(argv)                              # rclpy.init(args=ros_args(argv))

``ros_args`` applies this project's DDS defaults (they must be set before rclpy.init, see
ros_tutorials_common/dds.py) and checks the ROS arguments, so that ``--ros-args -r bad`` ends
the program with one clear line and exit status 1 instead of a traceback from rclpy.init.
``user_args`` is the command line without the ROS arguments, for argparse. ``init`` does both
steps at once.

``ros_args`` also orders the two things a Ctrl-C does (``_RosDown``): rclpy's signal handler
shuts ROS down in a thread of its own, and Python raises KeyboardInterrupt in the main thread.
Left to chance, the program's ``except KeyboardInterrupt`` / ``finally: rclpy.try_shutdown()``
can run while that thread is still shutting down: try_shutdown then fails with "rcl_shutdown
already called", and the node ends killed by SIGINT (status 130) instead of exiting 0.

How a node of the toolkit stops is ros_tutorials_common/shutdown.py's design; its rclpy half is
here: ``NODE_STOPPED`` and ``node_stopped`` (what ends a node's spin normally), ``run_node``,
``SpinThread`` (a node spun in a thread of its own, stopped before its executor), and
``ThreadRequests`` (work handed from another thread to the thread that spins a node).
"""

from __future__ import annotations

import queue
import signal
import sys
import threading
import time
from collections.abc import Callable, Sequence

import rclpy
from rclpy.context import Context
from rclpy.exceptions import NotInitializedException
from rclpy.executors import Executor, ExternalShutdownException, SingleThreadedExecutor
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy  # see RCLError
from rclpy.impl.rcutils_logger import RcutilsLogger
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions, get_current_signal_handlers_options
from rclpy.utilities import remove_ros_args

from ros_tutorials_common import shutdown
from ros_tutorials_common.dds import apply_dds_defaults, environment_problem

# The error rcl raises (malformed ROS arguments, publishing after shutdown). rclpy Jazzy exports
# it nowhere public (not in rclpy.exceptions; rclpy's own modules take it from the private
# rclpy.impl.implementation_singleton too), so this is the project's one import of a private
# rclpy module: everything else takes RCLError from ros_tutorials_common.ros.
RCLError = _rclpy.RCLError
# The logger with no name, which C++'s RCUTILS_LOG_* macros write with ("[ERROR] [...] []: ...",
# tf2's core): rclpy.logging.get_logger refuses an empty name; its root logger is this class's.
UNNAMED_LOGGER = RcutilsLogger()


def user_args(argv: Sequence[str] | None = None) -> list[str]:
    """The command-line arguments meant for the program (sys.argv unless argv), without the
    program's name and the ROS ones. Malformed ROS arguments end the program with one line."""
    argv = sys.argv if argv is None else argv
    try:
        return remove_ros_args(args=list(argv))[1:]
    except RCLError as error:
        reason = str(error).split(", at ")[0]  # rcl appends its source file and line
        raise SystemExit(f"error: invalid ROS arguments: {reason}") from None


def ros_args(argv: Sequence[str] | None = None) -> list[str]:
    """The command line to give rclpy.init (sys.argv unless argv), checked, with this
    project's DDS defaults applied to the environment first, and Ctrl-C raising
    KeyboardInterrupt only once ROS is shut down (see the module's docstring)."""
    argv = list(sys.argv if argv is None else argv)
    user_args(argv)  # ends the program with one line if the ROS arguments are malformed
    problem = environment_problem()  # ROS_DOMAIN_ID=abc, an unwritable ROS_LOG_DIR, ...
    if problem:
        raise SystemExit(f"error: {problem}")
    apply_dds_defaults()
    _RosDown.install()
    return argv


class _RosDown:
    """What shutdown.py's Ctrl-C handler does before it raises KeyboardInterrupt in a program of
    this project: wait until rclpy's signal handler has shut the default context down (at most
    ``WAIT`` seconds), when rclpy handles SIGINT at all.

    Installed before rclpy.init, which then installs rclpy's handler in front of Python's and
    calls it after its own. Reads the context's handle, not Context.ok(): a signal handler must
    not take a lock that the code it interrupted may hold.
    """

    WAIT = 2.0

    def __init__(self, context: Context) -> None:
        self.context = context

    @classmethod
    def install(cls) -> None:
        if threading.current_thread() is not threading.main_thread():
            return  # signal.signal works in the main thread only
        if signal.getsignal(signal.SIGINT) is signal.default_int_handler:  # not the program's
            shutdown.count_presses()
        if shutdown.counts_presses():
            shutdown.before_ctrl_c = cls(rclpy.get_default_context())

    def ros_is_up(self) -> bool:
        handle = self.context.handle
        try:
            return handle is not None and handle.ok()
        except Exception:  # destroyed meanwhile: down
            return False

    def wait_until_down(self, timeout: float) -> bool:
        """Whether the context is down (now, or before timeout seconds have passed)."""
        deadline = time.monotonic() + timeout
        while self.ros_is_up():
            if time.monotonic() >= deadline:
                return False
            time.sleep(0.001)
        return True

    def __call__(self) -> None:
        options = get_current_signal_handlers_options()
        if options in (SignalHandlerOptions.SIGINT, SignalHandlerOptions.ALL):
            self.wait_until_down(self.WAIT)


# What ends a node's spin normally: Ctrl-C; SIGTERM (rclpy's handler shut ROS down:
# ExternalShutdownException); rclpy refusing a node or an executor in the context a signal has
# just shut down (NotInitializedException); and rcl seeing it first (shutdown.is_shutdown_race).
NODE_STOPPED = (KeyboardInterrupt, ExternalShutdownException, NotInitializedException)


def node_stopped(error: BaseException) -> bool:
    """Whether ERROR is how a Ctrl-C or SIGTERM ended a node's spin: the stop, not a failure."""
    return isinstance(error, NODE_STOPPED) or shutdown.is_shutdown_race(error)


class SpinThread:
    """NODE spun in a thread of its own (tf2's TransformListener(spin_thread=True),
    turtle_teleop_key) until ROS shuts down or ``stop()``.

    ``stop()`` ends the thread, then shuts its executor down. In that order: rclpy's
    Executor.shutdown destroys the executor's guard condition at once, also under a thread that
    waits on it, which then fails ("InvalidHandle: cannot use Destroyable because destruction
    was requested"). The thread's spin returns only for work (rclpy's executor waits again after
    its own wake), so ``stop()`` triggers a guard condition of the node's.
    """

    def __init__(self, node: Node, name: str, executor: Executor | None = None) -> None:
        """EXECUTOR, if given, knows which of the node's callbacks it runs (tf2's listener
        takes its own subscriptions without taking the node): it is not given the node."""
        self.node = node
        self.adds_node = executor is None
        self.executor = executor or SingleThreadedExecutor(context=node.context)
        self.running = True
        self.wake = node.create_guard_condition(lambda: None)
        self.thread = threading.Thread(target=self._spin, name=name, daemon=True)
        self.thread.start()

    def _spin(self) -> None:
        if self.adds_node:
            self.executor.add_node(self.node)
        try:
            while self.running:
                self.executor.spin_once()
        except Exception as error:
            if not node_stopped(error):  # ROS shut down (Ctrl-C, SIGTERM): the spin is over
                raise

    def stop(self) -> None:
        """End the thread (its callback running now finishes first), then the executor."""
        if not self.running:
            return
        self.running = False
        if self.thread.is_alive():
            try:
                self.wake.trigger()
            except Exception:  # the node is destroyed already, its guard with it:
                self.executor.shutdown()  # the executor's own wake ends the spin, racing
        if threading.current_thread() is not self.thread:
            self.thread.join()
        self.executor.shutdown()


def init(
    argv: Sequence[str] | None = None,
    signal_handler_options: SignalHandlerOptions | None = None,
) -> None:
    """rclpy.init with the DDS defaults and checked ROS arguments (for the tools)."""
    rclpy.init(args=ros_args(argv), signal_handler_options=signal_handler_options)


def run_node(make_node: Callable[[], Node], argv: Sequence[str] | None = None) -> int:
    """A program that is one node (turtlesim's mimic, draw_square, the tf2 tools,
    robot_state_publisher): ``init``, make the node, spin it until Ctrl-C or shutdown, destroy
    it, shut ROS down; the exit status, 0. An error of MAKE_NODE's, or of a callback, raises
    after the same end."""
    init(argv)
    executor = SingleThreadedExecutor()  # made first: Ctrl-C may come as soon as the node is up
    node = None
    try:
        node = make_node()
        rclpy.spin(node, executor)
    except BaseException as error:
        if not node_stopped(error):
            raise
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0


class ThreadRequests:
    """Functions handed from any thread (a web server's event loop) to the thread that spins
    NODE, run there in the order given: ``requests(change)`` queues one and triggers a guard
    condition of NODE's, whose callback runs all that are queued, then ``after()``."""

    def __init__(self, node: Node, after: Callable[[], None] | None = None) -> None:
        self._queue: queue.SimpleQueue[Callable[[], None]] = queue.SimpleQueue()
        self._after = after
        self._wake = node.create_guard_condition(self._run)

    def __call__(self, change: Callable[[], None]) -> None:
        self._queue.put(change)
        self._wake.trigger()

    def _run(self) -> None:
        while True:
            try:
                change = self._queue.get_nowait()
            except queue.Empty:
                break
            change()
        if self._after is not None:
            self._after()
