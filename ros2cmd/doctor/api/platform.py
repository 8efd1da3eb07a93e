"""The platform: ROS_DISTRO, the Python and the virtual environment the wheels need, and the
reports of the platform and of the distribution (the installed wheels')."""

from __future__ import annotations

import platform
import re
import sys
import sysconfig

from ros2cmd.doctor.api import Report, Result, doctor_error, doctor_warn
from ros2cmd.doctor.api.package import DISTRIBUTION, python_range
from ros2cmd.doctor.api.system import Doctor


def platform_check(run: Doctor) -> Result:
    result = Result()
    distro = run.settings.ros_distro
    if distro and distro.lower() != DISTRIBUTION:
        doctor_warn(
            f"ROS_DISTRO is {distro}, but this environment's ROS 2 is {DISTRIBUTION} "
            "(the wheels): a ROS installation sourced in this terminal may mix in"
        )
        result.warning += 1
    supported = python_range()
    version = platform.python_version()
    if supported and not _python_in(supported):
        doctor_error(f"Python {version} is outside the wheels' range ({supported})")
        result.error += 1
    if sys.prefix == sys.base_prefix:
        doctor_error(
            "not in a virtual environment: the ROS 2 wheels find their libraries only "
            "inside one (make setup creates .venv)"
        )
        result.error += 1
    return result


def platform_report(run: Doctor) -> Report:
    report = Report("PLATFORM INFORMATION")
    report.add("system", platform.system())
    report.add("platform info", platform.platform())
    report.add("release", platform.release())
    report.add("processor", platform.processor())
    report.add("python", f"{platform.python_version()} ({sys.executable})")
    venv = sys.prefix if sys.prefix != sys.base_prefix else "none"
    report.add("virtual environment", venv)
    return report


def rosdistro_report(run: Doctor) -> Report:
    """ros2doctor reads rosdistro; here the distribution of the installed wheels."""
    report = Report("ROS 2 INFORMATION")
    report.add("distribution name", DISTRIBUTION)
    report.add("distribution type", "ros2")
    report.add("distribution status", "active")
    report.add("release platforms", {"pypi": wheel_platforms()})
    return report


def _python_in(specifier: str) -> bool:
    """Whether this Python satisfies `>=3.10,<3.14` (the simple forms pyproject uses)."""
    current = sys.version_info[:2]
    for part in specifier.split(","):
        match = re.fullmatch(r"\s*(>=|<=|<|>|==)\s*(\d+)\.(\d+)\s*", part)
        if not match:
            continue
        bound = (int(match.group(2)), int(match.group(3)))
        op = match.group(1)
        if not {
            ">=": current >= bound,
            "<=": current <= bound,
            "<": current < bound,
            ">": current > bound,
            "==": current == bound,
        }[op]:
            return False
    return True


def wheel_platforms() -> list[str]:
    """Where the wheels of this environment run: this platform, the Pythons they support."""
    return [f"{sysconfig.get_platform()}, Python {python_range() or '?'}"]
