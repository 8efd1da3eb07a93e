"""The ROS side of a web server's requests: work asked for from the event loop and done on
the node's thread (its executor spins in a thread of its own, server.py), and service calls
awaited there."""

from __future__ import annotations

import asyncio
import time
from collections.abc import Callable
from typing import Any

from ros_tutorials_web.forms import Refused

CALL_TIMEOUT = 10.0  # s: a service that does not answer within it is said so


class Ros:
    """The node's work, asked for from the event loop: ``run(fn)`` runs fn on the ROS thread
    (``request``, e.g. Watcher.request) and gives its result; ``future(f)`` awaits an rclpy
    future."""

    def __init__(self, node: Any, request: Callable[[Callable[[], None]], None]) -> None:
        self.node = node
        self.request = request

    async def run(self, work: Callable[[], Any]) -> Any:
        loop = asyncio.get_running_loop()
        done: asyncio.Future = loop.create_future()

        def on_ros() -> None:
            try:
                result = work()
            except Exception as error:
                loop.call_soon_threadsafe(_settle, done, None, error)
            else:
                loop.call_soon_threadsafe(_settle, done, result, None)

        self.request(on_ros)
        return await done

    async def future(self, rclpy_future: Any, timeout: float, what: str) -> Any:
        loop = asyncio.get_running_loop()
        done: asyncio.Future = loop.create_future()
        rclpy_future.add_done_callback(
            lambda f: loop.call_soon_threadsafe(_settle, done, f.result(), f.exception())
        )
        try:
            return await asyncio.wait_for(done, timeout)
        except asyncio.TimeoutError:
            raise Refused(f"{what}: no answer within {timeout:.0f} s") from None

    async def call(self, service: str, service_class: type, request: Any, what: str) -> Any:
        """One call of ``service``: a client made for it, the answer, the client destroyed."""
        client = await self.run(lambda: self.node.create_client(service_class, service))
        try:
            deadline = time.monotonic() + CALL_TIMEOUT
            while not client.service_is_ready():
                if time.monotonic() > deadline:
                    raise Refused(f"{what}: service '{service}' not available")
                await asyncio.sleep(0.05)
            rclpy_future = await self.run(lambda: client.call_async(request))
            return await self.future(rclpy_future, CALL_TIMEOUT, what)
        finally:
            await self.run(lambda: self.node.destroy_client(client))


def _settle(done: asyncio.Future, result: Any, error: BaseException | None) -> None:
    if done.done():
        return
    if error is not None:
        done.set_exception(error)
    else:
        done.set_result(result)
