"""The commands on PATH: ``rviz2`` (as a ROS 2 installation's bin/ has it) and ROS 1's
``rviz``. Both run rviz2.py's main, which is also ``ros2 run rviz2 rviz2`` (the package's
executable: a module with a main(), as packages.py finds them)."""

from __future__ import annotations

from collections.abc import Sequence

from rviz2 import rviz2 as view


def rviz2(argv: Sequence[str] | None = None) -> int:
    return view.main(argv)


def rviz(argv: Sequence[str] | None = None) -> int:
    """ROS 1's ``rviz``: the same view (``-d`` and ``-f`` as rviz has them)."""
    return view.main(argv, prog="rviz")
