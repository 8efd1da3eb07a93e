"""Child processes of the service benchmark.

    python -m benchmarks.service_worker server                         a bare rclpy server
    python -m benchmarks.service_worker client {tutorial,bare} COUNT SERVER_PID

The client prints one JSON line: the round-trip times, and the CPU time per call of itself
and of the server process (every thread: rclpy's and the DDS library's), over the timed
calls only. "tutorial" logs the book's two lines per call, as the tutorial's service_client
does; "bare" logs nothing. Both send each request and spin_once until its answer (REFERENCE
section 3: spin_until_future_complete costs milliseconds per call, which a loop must not pay).
ROS arguments pass through (e.g. ``--ros-args --log-level warn``).
"""

from __future__ import annotations

import contextlib
import json
import os
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


def cpu_seconds(pid: int) -> float:
    """User + system CPU time of a process so far (all its threads)."""
    with open(f"/proc/{pid}/stat") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def round_trips(kind: str, count: int, server: int) -> dict[str, object]:
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
        if i == 50:  # the first ones warm caches and allocators: not counted
            own, served = time.process_time(), cpu_seconds(server)
        request = SrvTutorial.Request(a=i, b=2)
        start = time.perf_counter()
        future = node.client.call_async(request)
        while not future.done():
            rclpy.spin_once(node, timeout_sec=1.0)
        report(request, future.result())
        samples.append(time.perf_counter() - start)
        assert future.result().result == i + 2
    return {
        "round_trip": samples[50:],
        "client_cpu": (time.process_time() - own) / count,
        "server_cpu": (cpu_seconds(server) - served) / count,
    }


def main() -> int:
    verb, *rest = user_args()
    init()
    if verb == "server":
        with contextlib.suppress(KeyboardInterrupt, ExternalShutdownException):
            rclpy.spin(BareServer())
        rclpy.try_shutdown()
        return 0
    print(json.dumps(round_trips(rest[0], int(rest[1]), int(rest[2]))), flush=True)
    rclpy.try_shutdown()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
