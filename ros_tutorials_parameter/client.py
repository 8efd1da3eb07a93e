"""Service client for the parameter lesson (book: service_client_with_parameter).

The same client as the service lesson's: sends A and B to ``ros_tutorial_srv`` once and logs
the result, which now depends on the server's ``calculation_method``.

    python -m ros_tutorials_parameter.client 10 5   (or: service_client_with_parameter 10 5)
"""

from ros_tutorials_common.service_client import call_once
from ros_tutorials_service.client import ServiceClient


def main() -> int:
    return call_once(ServiceClient, "service_client_with_parameter")


if __name__ == "__main__":
    raise SystemExit(main())
