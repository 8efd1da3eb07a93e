"""Child processes of the service benchmark.

    python -m benchmarks.service_worker server          a bare rclpy SrvTutorial server
    python -m benchmarks.service_worker client {tutorial,bare} COUNT

The client prints one JSON line of round-trip times. "tutorial" logs the book's two lines per
call, as the tutorial's service_client does; "bare" logs nothing. Both send each request and
spin_once until its answer (REFERENCE section 3: spin_until_future_complete costs
milliseconds per call, which a loop must not pay).
ROS arguments pass through (e.g. ``--ros-args --log-level warn``).
"""

from __future__ import annotations

import contextlib
import json
import time

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import SrvTutorial

from ros_tutorials_common.ros import init, user_args

SERVICE = "ros_tutorial_srv"


class BareServer(Node):
    def __init__(self) -> None:
        super().__init__("bare_server")
        self.service = self.create_service(SrvTutorial, SERVICE, self.add)

    def add(self, request: SrvTutorial.Request, response: SrvTutorial.Response):
        response.result = request.a + request.b
        return response


def round_trips(kind: str, count: int) -> list[float]:
    node = Node(f"{kind}_client")
    node.client = node.create_client(SrvTutorial, SERVICE)

    def report(request, response) -> None:
        if kind == "tutorial":  # the two log lines of ros_tutorials_service/client.py
            node.get_logger().info(f"send srv, srv.Request.a and b: {request.a}, {request.b}")
            node.get_logger().info(f"receive srv, srv.Response.result: {response.result}")

    while not node.client.service_is_ready():
        rclpy.spin_once(node, timeout_sec=0.05)
    samples = []
    for i in range(count + 50):
        request = SrvTutorial.Request(a=i, b=2)
        start = time.perf_counter()
        future = node.client.call_async(request)
        while not future.done():
            rclpy.spin_once(node, timeout_sec=1.0)
        report(request, future.result())
        samples.append(time.perf_counter() - start)
        assert future.result().result == i + 2
    return samples[50:]  # the first ones warm caches and allocators


def main() -> int:
    verb, *rest = user_args()
    init()
    if verb == "server":
        with contextlib.suppress(KeyboardInterrupt, ExternalShutdownException):
            rclpy.spin(BareServer())
        rclpy.try_shutdown()
        return 0
    print(json.dumps({"round_trip": round_trips(rest[0], int(rest[1]))}), flush=True)
    rclpy.try_shutdown()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
