"""Service client (book: ros_tutorials_service/service_client).

Sends the two numbers of its command line to ``ros_tutorial_srv`` once, logs the request and
the result, and exits. Without a server it waits up to ``--timeout`` seconds (default 5),
then fails with exit status 1.

    python -m ros_tutorials_service.client 2 3   (or: service_client 2 3)
"""

from rclpy.node import Node
from ros_tutorials_interfaces.srv import SrvTutorial

from ros_tutorials_common.service_client import call_once


class ServiceClient(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("service_client", enable_logger_service=True, **node_kwargs)
        self.client = self.create_client(SrvTutorial, "ros_tutorial_srv")

    def report(self, request: SrvTutorial.Request, response: SrvTutorial.Response) -> None:
        log = self.get_logger()
        log.info(f"send srv, srv.Request.a and b: {request.a}, {request.b}")
        log.info(f"receive srv, srv.Response.result: {response.result}")


def main() -> int:
    return call_once(ServiceClient, "service_client")


if __name__ == "__main__":
    raise SystemExit(main())
