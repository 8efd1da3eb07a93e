"""What `ros2 bag`'s verbs share, as ros2bag's api has it: its `[ERROR] [ros2bag]: ...` and
`[WARN] [ros2bag]: ...` lines, its argparse checks, the reader's arguments, and the refusal of
what this project does not implement."""

from __future__ import annotations

import argparse
import math
import os
import sys

from ros2cmd.errors import ToolError
from ros_tutorials_common.names import SERVICE_EVENT_SUFFIX

STORAGES = ["mcap", "sqlite3"]  # what a Jazzy install registers
MCAP_PRESETS = ["none", "fastwrite", "zstd_fast", "zstd_small"]  # rosbag2_storage_mcap's
LOG_LEVELS = ["debug", "info", "warn", "error", "fatal"]


def print_error(text: str) -> str:
    return f"[ERROR] [ros2bag]: {text}"


def print_warn(text: str) -> str:
    return f"[WARN] [ros2bag]: {text}"


def fail(text: str) -> None:
    """ros2bag's way out: its error line on stderr, exit status 1 (ros2cli's sys.exit(str))."""
    print(print_error(text), file=sys.stderr, flush=True)
    raise SystemExit(1)


def not_supported(what: str, why: str) -> ToolError:
    return ToolError(f"not supported here: {what} ({why})")


def service_event_topics(services: list[str] | None) -> list[str]:
    """ros2bag's convert_service_to_service_event_topic."""
    return [service + SERVICE_EVENT_SUFFIX for service in services or []]


# ros2bag.api's argparse checks


def check_positive_float(value: str) -> float:
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{value} is not the valid type (float)") from None
    if not (number > 0.0 and math.isfinite(number)):  # nan and inf: never a usable rate
        raise argparse.ArgumentTypeError(f"{value} is not in the valid range (> 0.0)")
    return number


def check_not_negative_float(value: str) -> float:
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{value} is not the valid type (float)") from None
    if not (number >= 0.0 and math.isfinite(number)):
        raise argparse.ArgumentTypeError(f"Value {value} is less than zero.")
    return number


def check_not_negative_int(value: str) -> int:
    try:
        number = int(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{value} is not the valid type (int)") from None
    if number < 0:
        raise argparse.ArgumentTypeError(f"Value {value} is less than zero.")
    return number


def positive_float(value: str) -> float:
    """play's own check (--delay, --clock): argparse reports "invalid positive_float value"."""
    number = float(value)
    if not (number > 0 and math.isfinite(number)):
        raise ValueError(f"Value {number} is less than or equal to zero.")
    return number


def check_path_exists(value: str) -> str:
    if os.path.exists(value):
        return value
    raise argparse.ArgumentTypeError(f"Bag path '{value}' does not exist!")


def add_reader_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("bag_path", type=check_path_exists, help="Bag to open")
    parser.add_argument(
        "-s",
        "--storage",
        default="",
        choices=STORAGES,
        help="Storage implementation of bag. "
        "By default attempts to detect automatically - use this argument to override.",
    )


def check_storage(storage: str) -> None:
    if storage == "sqlite3":
        raise not_supported("--storage sqlite3", "bags here are mcap, Jazzy's default storage")


def set_log_level(level: str, *loggers: str) -> None:
    import rclpy.logging

    severity = getattr(rclpy.logging.LoggingSeverity, level.upper())
    for name in loggers:
        rclpy.logging.set_logger_level(name, severity)
