"""turtlesim's parameters: upstream's (``background_r/g/b``, ``holonomic``) and this project's
(``headless``, ``snapshot_path``, ``snapshot_on_exit``), and the rule for where a snapshot
may be written.

Any process of the domain can set parameters, so a ``snapshot_path`` set while running must
be in the folder turtlesim was started in (or be the one it was started with).
"""

from __future__ import annotations

import os

from rcl_interfaces.msg import IntegerRange, ParameterDescriptor, SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter

DEFAULT_BACKGROUND = (69, 86, 255)  # 0x45, 0x56, 0xff


def default_snapshot_name(node: str) -> str:
    """turtlesim.png for /turtlesim; for another name its own file (/turtlesim1/sim:
    turtlesim1_sim.png), so that two simulators started together do not write one file."""
    return "turtlesim.png" if node == "/turtlesim" else node.strip("/").replace("/", "_") + ".png"


def declare_parameters(node: Node) -> None:
    """Every parameter but ``headless``'s final, read-only declaration (declare_headless)."""
    channel = IntegerRange(from_value=0, to_value=255, step=1)
    for name, value in zip("rgb", DEFAULT_BACKGROUND, strict=True):
        node.declare_parameter(
            f"background_{name}",
            value,
            ParameterDescriptor(
                description=f"{dict(r='Red', g='Green', b='Blue')[name]} channel of the "
                "background color",
                integer_range=[channel],
            ),
        )
    node.declare_parameter(
        "holonomic",
        False,
        ParameterDescriptor(description="If true, then turtles will be holonomic"),
    )
    # Declared again, read-only, once it is known whether a window opened.
    node.declare_parameter("headless", False)
    node.declare_parameter(
        "snapshot_path",
        default_snapshot_name(node.get_fully_qualified_name()),
        ParameterDescriptor(description="Where ~/snapshot, SIGUSR1 and the exit write the PNG"),
    )
    node.declare_parameter(
        "snapshot_on_exit",
        False,
        ParameterDescriptor(description="Write the canvas to snapshot_path when the node ends"),
    )


def declare_headless(node: Node, headless: bool) -> None:
    """``headless`` again, read-only: whether a window is open (true also when none could)."""
    node.undeclare_parameter("headless")
    node.declare_parameter(
        "headless",
        headless,
        ParameterDescriptor(
            description="Never open a window (true also when none could open)", read_only=True
        ),
        ignore_override=True,
    )


class SnapshotPaths:
    """Where a snapshot may be written: in the folder turtlesim was started in (links
    followed; relative paths are relative to it), or to the path it was started with (the
    command line's or a launch file's, allowed anywhere)."""

    def __init__(self, started_with: str) -> None:
        self.home = os.path.realpath(os.getcwd())
        self.started_with = os.path.abspath(started_with)

    def outside(self, value: str) -> str | None:
        """Why a snapshot may not be written to value (None: it may)."""
        path = os.path.abspath(value)
        if path == self.started_with:
            return None
        if os.path.commonpath([os.path.realpath(path), self.home]) == self.home:
            return None
        return (
            f"snapshot_path {value} is outside the folder turtlesim was started in "
            f"({self.home}): only a path in there may be set while it runs"
        )

    def check(self, parameters: list[Parameter]) -> SetParametersResult:
        """The node's on-set-parameters callback: a snapshot_path outside is refused."""
        for parameter in parameters:
            if parameter.name == "snapshot_path" and not str(parameter.value):
                return SetParametersResult(successful=False, reason="snapshot_path is empty")
            if parameter.name == "snapshot_path":
                outside = self.outside(str(parameter.value))
                if outside:
                    return SetParametersResult(successful=False, reason=outside)
        return SetParametersResult(successful=True)
