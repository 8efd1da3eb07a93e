"""tf2_ros.Buffer: tf2's BufferCore with waiting lookups, as rclpy code uses it.

``lookup_transform(target, source, time, timeout)`` waits up to TIMEOUT for the transform to
become possible, then looks it up (raising tf2's exception if it still is not);
``can_transform`` answers the same question without raising. ``rclpy.time.Time()`` as the time
means the latest time all frames on the way have data for. The waits are woken by new data
(a condition the TransformListener's callbacks notify), not by polling. Given a node, the buffer
answers the ``tf2_frames`` service (tf2_msgs/srv/FrameGraph: the frames as YAML, what
view_frames reads), and a jump back of the node's clock (a bag replayed in a loop) clears it.
"""

from __future__ import annotations

import threading
import time as wall
from collections.abc import Callable
from typing import Any

import rclpy.logging
from rclpy.clock import Clock, JumpThreshold, TimeJump
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.task import Future
from rclpy.time import Time
from tf2_msgs.srv import FrameGraph

from tf2_py import BufferCore
from tf2_py.buffer_core import to_nanoseconds
from tf2_ros.buffer_interface import NO_TIMEOUT, BufferInterface

__all__ = ["Buffer"]


class Buffer(BufferCore, BufferInterface):
    """Known frames over the last CACHE_TIME (default 10 s), and the lookups through them."""

    def __init__(self, cache_time: Duration | None = None, node: Node | None = None) -> None:
        BufferCore.__init__(self, cache_time)
        BufferInterface.__init__(self)
        self._new_data = threading.Condition()
        self._new_data_callbacks: list[Callable[[], None]] = []
        if node is not None:
            self.srv = node.create_service(FrameGraph, "tf2_frames", self._frames)
            self.clock = node.get_clock()
        else:
            self.clock = Clock()
        threshold = JumpThreshold(
            min_forward=None, min_backward=Duration(seconds=-1), on_clock_change=True
        )
        self.jump_handle = self.clock.create_jump_callback(
            threshold, post_callback=self.time_jump_callback
        )

    def _frames(self, request: Any, response: Any) -> Any:
        return FrameGraph.Response(frame_yaml=self.all_frames_as_yaml())

    def time_jump_callback(self, time_jump: TimeJump) -> None:
        rclpy.logging.get_logger("tf2_buffer").warning(
            "Detected jump back in time. Clearing tf buffer."
        )
        self.clear()

    def set_transform(self, transform: Any, authority: str) -> None:
        super().set_transform(transform, authority)
        self._notify()

    def set_transform_static(self, transform: Any, authority: str) -> None:
        super().set_transform_static(transform, authority)
        self._notify()

    def set_transforms(self, transforms: Any, authority: str, is_static: bool = False) -> None:
        """A TFMessage's transforms at once: the waiting lookups are woken once for them."""
        super().set_transforms(transforms, authority, is_static)
        self._notify()

    def _notify(self) -> None:
        with self._new_data:
            self._new_data.notify_all()
            callbacks = list(self._new_data_callbacks)
        for callback in callbacks:
            callback()

    def _wait(self, timeout: Any, possible: Callable[[], bool]) -> None:
        """Until POSSIBLE() or TIMEOUT (a Duration) has passed; returns at once for 0."""
        seconds = to_nanoseconds(timeout, "duration") / 1e9
        if seconds <= 0:
            return
        deadline = wall.monotonic() + seconds
        with self._new_data:
            while not possible():
                remaining = deadline - wall.monotonic()
                if remaining <= 0:
                    return
                self._new_data.wait(min(remaining, 0.5))  # and look again: data may be static

    # -- the simple API ------------------------------------------------------------------------

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Time, timeout: Duration = NO_TIMEOUT
    ) -> Any:
        """The transform from SOURCE_FRAME to TARGET_FRAME at TIME; waits up to TIMEOUT."""
        self._wait(timeout, lambda: self.can_transform_core(target_frame, source_frame, time)[0])
        return self.lookup_transform_core(target_frame, source_frame, time)

    def can_transform(
        self,
        target_frame: str,
        source_frame: str,
        time: Time,
        timeout: Duration = NO_TIMEOUT,
        return_debug_tuple: bool = False,
    ) -> Any:
        """Whether the lookup is possible (waiting up to TIMEOUT); with RETURN_DEBUG_TUPLE,
        (bool, tf2's message)."""
        self._wait(timeout, lambda: self.can_transform_core(target_frame, source_frame, time)[0])
        result = self.can_transform_core(target_frame, source_frame, time)
        return result if return_debug_tuple else result[0]

    # -- the advanced API: time travel ---------------------------------------------------------

    def lookup_transform_full(
        self,
        target_frame: str,
        target_time: Time,
        source_frame: str,
        source_time: Time,
        fixed_frame: str,
        timeout: Duration = NO_TIMEOUT,
    ) -> Any:
        """SOURCE_FRAME at SOURCE_TIME into TARGET_FRAME at TARGET_TIME, through FIXED_FRAME."""
        arguments = (target_frame, target_time, source_frame, source_time, fixed_frame)
        self._wait(timeout, lambda: self.can_transform_full_core(*arguments)[0])
        return self.lookup_transform_full_core(
            target_frame, target_time, source_frame, source_time, fixed_frame
        )

    def can_transform_full(
        self,
        target_frame: str,
        target_time: Time,
        source_frame: str,
        source_time: Time,
        fixed_frame: str,
        timeout: Duration = NO_TIMEOUT,
        return_debug_tuple: bool = False,
    ) -> Any:
        arguments = (target_frame, target_time, source_frame, source_time, fixed_frame)
        self._wait(timeout, lambda: self.can_transform_full_core(*arguments)[0])
        result = self.can_transform_full_core(*arguments)
        return result if return_debug_tuple else result[0]

    # -- waiting without blocking: futures -----------------------------------------------------

    def wait_for_transform_async(self, target_frame: str, source_frame: str, time: Time) -> Future:
        """A Future done with the transform once it is possible."""
        return self._future(
            lambda: self.can_transform_core(target_frame, source_frame, time)[0],
            lambda: self.lookup_transform_core(target_frame, source_frame, time),
        )

    def wait_for_transform_full_async(
        self,
        target_frame: str,
        target_time: Time,
        source_frame: str,
        source_time: Time,
        fixed_frame: str,
    ) -> Future:
        arguments = (target_frame, target_time, source_frame, source_time, fixed_frame)
        return self._future(
            lambda: self.can_transform_full_core(*arguments)[0],
            lambda: self.lookup_transform_full_core(*arguments),
        )

    def _future(self, possible: Callable[[], bool], lookup: Callable[[], Any]) -> Future:
        future = Future()
        lock = threading.Lock()

        def on_new_data() -> None:
            with lock:
                if not future.done() and possible():
                    try:
                        future.set_result(lookup())
                    except Exception as error:  # to the awaiting code, not the listener's
                        future.set_exception(error)
                if not future.done():
                    return
            forget(future)

        def forget(_: Future) -> None:
            with self._new_data:
                if on_new_data in self._new_data_callbacks:
                    self._new_data_callbacks.remove(on_new_data)

        with self._new_data:
            self._new_data_callbacks.append(on_new_data)
        future.add_done_callback(forget)  # a cancelled wait too
        on_new_data()
        return future

    async def lookup_transform_async(self, target_frame: str, source_frame: str, time: Time) -> Any:
        return await self.wait_for_transform_async(target_frame, source_frame, time)

    async def lookup_transform_full_async(
        self,
        target_frame: str,
        target_time: Time,
        source_frame: str,
        source_time: Time,
        fixed_frame: str,
    ) -> Any:
        return await self.wait_for_transform_full_async(
            target_frame, target_time, source_frame, source_time, fixed_frame
        )
