"""64-bit integers, as in ``int64 a``: parse them from the command line, keep results in range.

Python integers never overflow, but a ROS ``int64`` field refuses anything outside
-2**63 .. 2**63-1 (rclpy raises when the value is assigned). A server that computed
``a + b`` from two large operands would then fail inside its callback, so it checks first.
"""

from __future__ import annotations

from rclpy.impl.rcutils_logger import RcutilsLogger

INT64_MIN = -(2**63)
INT64_MAX = 2**63 - 1


def parse_int64(text: str) -> int:
    """The int64 written in text; ValueError with a readable message if it is not one."""
    try:
        value = int(text)
    except ValueError:
        raise ValueError(f"{text!r} is not an integer") from None
    if not INT64_MIN <= value <= INT64_MAX:
        raise ValueError(f"{text} does not fit in a 64-bit integer ({INT64_MIN} .. {INT64_MAX})")
    return value


def int64_or_zero(value: int, expression: str, logger: RcutilsLogger) -> int:
    """value if it fits in an int64; otherwise 0 and a warning naming the expression.

    The tutorial services have no error field, so an unrepresentable result is answered
    with 0 (defined, and what the book's division by zero answers) and explained in the log.
    """
    if INT64_MIN <= value <= INT64_MAX:
        return value
    logger.warning(f"{expression} = {value} does not fit in int64; sending back 0 instead")
    return 0
