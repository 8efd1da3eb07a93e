"""64-bit integers, as in ``int64 a``: keep the servers' results in range.

Python integers never overflow, but a ROS ``int64`` field refuses anything outside
-2**63 .. 2**63-1 (rclpy raises when the value is assigned). A server that computed
``a + b`` from two large operands would then fail inside its callback, so it checks first.
"""

from __future__ import annotations

from typing import Protocol

INT64_MIN = -(2**63)
INT64_MAX = 2**63 - 1


class Logger(Protocol):
    """What int64_or_zero needs of a logger (a node's get_logger() is one); no rclpy here."""

    def warning(self, message: str) -> object: ...


def int64_or_zero(value: int, expression: str, logger: Logger) -> int:
    """value if it fits in an int64; otherwise 0 and a warning naming the expression.

    The tutorial services have no error field, so an unrepresentable result is answered
    with 0 (defined, and what the book's division by zero answers) and explained in the log.
    """
    if INT64_MIN <= value <= INT64_MAX:
        return value
    logger.warning(f"{expression} = {value} does not fit in int64; sending back 0 instead")
    return 0
