"""Service client for the parameter lesson (book: ros_tutorials_parameter/service_client).

The book changes only the server in this lesson; its client is the service lesson's client
under another name, and so is this one: read ros_tutorials_service/client.py. It sends A and B
to ``ros_tutorial_srv`` once and logs the result, which now depends on the server's parameter
``calculation_method``.

    service_client_with_parameter 10 5   (or: python -m ros_tutorials_parameter.client 10 5)
"""

import sys

from ros_tutorials_service import client


def main(args=None) -> int:
    return client.main(args, prog="service_client_with_parameter")


if __name__ == "__main__":
    sys.exit(main())
