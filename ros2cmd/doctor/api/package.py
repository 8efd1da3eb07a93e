"""The packages: this project's packages in this environment's ament index, the pinned ROS 2
wheels, and their versions (what ros2doctor learns from rosdistro comes from the wheels)."""

from __future__ import annotations

import re
import sys
from pathlib import Path

from ros2cmd.doctor.api import Report, Result, doctor_error, doctor_warn
from ros2cmd.doctor.api.system import Doctor

DISTRIBUTION = "jazzy"  # the ROS 2 of the pinned wheels (ros-jazzy-*)
PROJECT = "ros-tutorials"


def package_check(run: Doctor) -> Result:
    result = Result()
    missing = [name for name in project_packages() if name not in local_packages()]
    if missing:
        doctor_error(
            f"packages of this project missing from the ament index of {sys.prefix}: "
            f"{' '.join(missing)}; run `make setup`"
        )
        result.error += 1
    for requirement, pinned, installed in pinned_wheels():
        if installed != pinned:
            doctor_warn(
                f"{requirement} is {installed or 'not installed'} here, this project pins "
                f"{pinned}: run `make setup`"
            )
            result.warning += 1
    return result


def package_report(run: Doctor) -> Report:
    """ros2doctor's `latest=` is rosdistro's release; here the pinned wheel's version."""
    report = Report("PACKAGE VERSIONS")
    wheels = wheel_versions()
    for name, local in local_packages().items():
        latest = wheels.get(f"ros-{DISTRIBUTION}-{name.replace('_', '-')}", "N/A")
        report.add(name, f"latest={latest}, local={local}")
    return report


def local_packages() -> dict[str, str]:
    """Every package in this environment's ament index and its package.xml version."""
    import xml.etree.ElementTree as ElementTree

    from ros_tutorials_common import ament

    found = {}
    for name, prefix in ament.packages().items():
        try:
            root = ElementTree.parse(prefix / "share" / name / "package.xml").getroot()
            found[name] = (root.findtext("version") or "").strip()
        except (OSError, ElementTree.ParseError):
            found[name] = ""
    return found


def project_packages() -> list[str]:
    """This project's packages: its Python packages with a package.xml, and its interfaces."""
    root = Path(__file__).resolve().parents[3]  # the checkout, above ros2cmd/doctor/api/
    names = [
        manifest.parent.name
        for pattern in ("ros_tutorials_*/package.xml", "interfaces/*/package.xml")
        for manifest in root.glob(pattern)
    ]
    return sorted(names)


def wheel_versions() -> dict[str, str]:
    """Installed distributions: normalised name -> version."""
    import importlib.metadata  # the doctor's report only: not to build the parser

    return {
        re.sub(r"[-_.]+", "-", dist.metadata["Name"]).lower(): dist.version
        for dist in importlib.metadata.distributions()
        if dist.metadata["Name"]
    }


def pinned_wheels() -> list[tuple[str, str, str | None]]:
    """The ROS 2 wheels this project pins: (name, pinned version, installed version)."""
    import importlib.metadata

    try:
        requirements = importlib.metadata.requires(PROJECT) or []
    except importlib.metadata.PackageNotFoundError:
        return []
    installed = wheel_versions()
    pinned = []
    for requirement in requirements:
        match = re.match(r"(ros-[a-z]+-[a-z0-9-]+)(\[[^]]*\])?==([^;\s]+)(.*)", requirement)
        if match and "extra ==" not in match.group(4):
            name = match.group(1)
            pinned.append((name, match.group(3), installed.get(name)))
    return pinned


def python_range() -> str | None:
    import importlib.metadata

    try:
        return importlib.metadata.metadata(PROJECT)["Requires-Python"]
    except (importlib.metadata.PackageNotFoundError, KeyError):
        return None
