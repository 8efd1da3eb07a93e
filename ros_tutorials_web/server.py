"""A web server of this project beside its ROS node: aiohttp (HTTP and WebSockets on asyncio)
on the main thread, the node spun by an executor in a thread of its own, the guard
(guard.py) in front of every route. Ctrl-C and SIGTERM are noted by shutdown.py's
``StopSignals``, whose wake ends the event loop's wait at once; the loop then closes the tabs,
stops the server and ends ROS in order.

Another tool's server (a 3D view, a sliders page) is run the same way::

    def make(loop):                       # on the event loop, after rclpy.init
        node = MyNode()
        hub = Hub(loop, node.request, start=node.start, stop=node.stop)
        app = web.Application(middlewares=[door.middleware(node.get_logger().warning)])
        app.on_shutdown.append(hub.close)
        ...                               # routes (guard.py says how)
        return node, app

    sock = guard.listen(args.host, args.port)     # before ROS starts: a taken port is one line
    door = guard.Guard.for_socket(sock, args.host, args.allow_origins)
    return server.run(argv, sock, door, make, exposed="see ... and publish ...")
"""

from __future__ import annotations

import asyncio
import socket
import threading
from collections.abc import Callable, Sequence

import rclpy
from aiohttp import web
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

from ros_tutorials_common.ros import init
from ros_tutorials_common.shutdown import StopSignals
from ros_tutorials_web.guard import Guard, greeting

Make = Callable[[asyncio.AbstractEventLoop], tuple[Node, web.Application]]


async def serve(sock: socket.socket, guard: Guard, make: Make, exposed: str, path: str) -> None:
    """Serve until Ctrl-C or SIGTERM, with the ROS node spinning in a thread of its own."""
    loop = asyncio.get_running_loop()
    stop = asyncio.Event()
    signals = StopSignals()  # Ctrl-C and SIGTERM noted (in this thread): the first ends the wait
    signals.wake = lambda: loop.call_soon_threadsafe(stop.set)
    node, app = make(loop)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    spinning = threading.Event()
    spinning.set()

    def spin() -> None:
        told: set[str] = set()
        while spinning.is_set():
            try:
                executor.spin_once(timeout_sec=0.2)
            except ExternalShutdownException:
                return
            except Exception as error:  # one callback's failure: the node goes on
                kind = type(error).__name__
                if kind not in told:  # once per kind: a callback failing at 30 Hz is no flood
                    told.add(kind)
                    node.get_logger().error(f"{kind} in a callback (the node goes on): {error}")

    thread = threading.Thread(target=spin, name="ros", daemon=True)
    thread.start()
    logger = node.get_logger()
    runner = web.AppRunner(app, handle_signals=False, access_log=None)
    await runner.setup()
    try:
        await web.SockSite(runner, sock, shutdown_timeout=1.0).start()
        first, *warnings = greeting(sock, guard, exposed, path)
        logger.info(first)
        for line in warnings:
            logger.warning(line)
        await stop.wait()
    finally:
        await runner.cleanup()  # the app's on_shutdown closes its tabs
        spinning.clear()
        executor.wake()
        thread.join()
        executor.shutdown()
        node.destroy_node()
        signals.restore()


def run(
    argv: Sequence[str], sock: socket.socket, guard: Guard, make: Make, exposed: str, path="/"
) -> int:
    """Start ROS (``argv``: the process's, for its --ros-args), serve, end in order."""
    try:
        # Ctrl-C and SIGTERM stop the event loop, which then ends ROS in order.
        init(list(argv), signal_handler_options=SignalHandlerOptions.NO)
        asyncio.run(serve(sock, guard, make, exposed, path))
    except KeyboardInterrupt:  # pressed before the event loop took Ctrl-C over
        pass
    finally:
        sock.close()
        rclpy.try_shutdown()
    return 0
