"""Interface type names: 'pkg/msg/Name' (ROS 2), 'pkg/Name' (ROS 1), and where they live.

Types are found the way ROS 2 finds them, through ament_index_python
(ros_tutorials_common/ament.py): the ament resource index lists, per package, the interface
files it installed (the resource rosidl_interfaces/PKG), the definitions are in the package's
share/PKG/{msg,srv,action}/, and the Python classes are imported from PKG.msg, PKG.srv,
PKG.action.
"""

from __future__ import annotations

import importlib
import os
import sys

from ros2cmd.errors import ToolError
from ros_tutorials_common import ament

# The seeds define their messages in their own package (pub_sub/Num, my_package/UserRecord,
# ros_tutorials_topic/MsgTutorial); here they all live in one interface package.
SEED_INTERFACES = "ros_tutorials_interfaces"

KINDS = ("msg", "srv", "action")
KIND_NAMES = {"msg": "message", "srv": "service", "action": "action"}


def interface_index() -> dict[str, list[str]]:
    """{package: ['msg/Num', 'srv/AddTwoInts', ...]} for every package in the index."""
    index: dict[str, list[str]] = {}
    for package in ament.resources("rosidl_interfaces"):
        names = index[package] = []
        for line in ament.resource("rosidl_interfaces", package).splitlines():
            stem, _, extension = line.strip().rpartition(".")
            if extension in KINDS and stem not in names:
                names.append(stem)
    return index


def interface_package(package: str, index: dict[str, list[str]]) -> str:
    """The interface package a package name stands for: itself if it has interfaces, else
    for a package of this project or a seed's name for one (ros_tutorials_common.packages'
    resolve_package: ros_tutorials_topic, pub_sub, service, ...) the one interface package."""
    from ros_tutorials_common.packages import resolve_package  # a seed's name: rarely asked

    if package not in index and resolve_package(package):
        return SEED_INTERFACES
    return package


def list_hint(kinds: tuple[str, ...]) -> str:
    """Where to look for the types that exist, in the spelling the user typed: the ROS 1
    tools' (`rosmsg list`) or ros2's (`ros2 interface list -m`)."""
    if os.path.basename(sys.argv[0]).startswith("ros2"):
        flag = {("msg",): " -m", ("srv",): " -s", ("action",): " -a"}.get(kinds, "")
        tool = f"ros2 interface list{flag}"
    else:
        tool = {("msg",): "rosmsg list", ("srv",): "rossrv list"}.get(kinds, "ros2 interface list")
    return f"`{tool}` shows every {'/'.join(KIND_NAMES[kind] for kind in kinds)} type"


def parse_type_name(name: str, kinds: tuple[str, ...] = KINDS) -> tuple[str, str, str]:
    """'pkg/msg/Name', 'pkg/Name' or 'Name[.msg]' -> (package, kind, Name), checked in the index."""
    parts = name.strip().split("/")
    base = parts[-1]
    for kind in KINDS:  # `rosmsg show UserRecord.msg` names the file
        if base.endswith("." + kind):
            base, kinds = base[: -len(kind) - 1], (kind,)
    if len(parts) == 3 and parts[1] in kinds:
        package, kinds = parts[0], (parts[1],)
    elif len(parts) == 2:
        package = parts[0]
    elif len(parts) == 1:
        package = None  # ROS 1 style: search every package
    else:
        expected = " or ".join(f"'pkg/{kind}/Name'" for kind in kinds)
        raise ToolError(f"invalid type name '{name}': expected {expected}")
    index = interface_index()
    named = package
    if package:
        package = interface_package(package, index)
    matches = _matches(index, [package] if package else sorted(index), kinds, base)
    what = "/".join(KIND_NAMES[kind] for kind in kinds)
    if not matches:
        elsewhere = _matches(index, sorted(index), kinds, base) if package else []
        if elsewhere:  # the right name in another package: say where it is
            found = " or ".join(f"{pkg}/{kind}/{base}" for pkg, kind, base in elsewhere)
            raise ToolError(f"unknown {what} type '{name}'; did you mean {found}?")
        if package and package not in index:
            raise ToolError(
                f"unknown {what} type '{name}': no interface package '{package}'; "
                + list_hint(kinds)
            )
        if package != named:
            raise ToolError(
                f"unknown {what} type '{name}': {named}'s types are in {package}, which has "
                f"no {what} '{base}'; " + list_hint(kinds)
            )
        raise ToolError(f"unknown {what} type '{name}'; " + list_hint(kinds))
    if len(matches) > 1 and package is None:
        found = ", ".join("/".join(match) for match in matches)
        raise ToolError(f"type name '{name}' is ambiguous: {found}; name the package")
    return matches[0]


def _matches(
    index: dict[str, list[str]], packages: list[str], kinds: tuple[str, ...], base: str
) -> list[tuple[str, str, str]]:
    return [
        (pkg, kind, base)
        for pkg in packages
        for kind in kinds
        if f"{kind}/{base}" in index.get(pkg, [])
    ]


def load_type(name: str, kinds: tuple[str, ...] = KINDS) -> type:
    """Import the Python class of an interface type, e.g. 'std_msgs/String' -> String."""
    package, kind, base = parse_type_name(name, kinds)
    try:
        module = importlib.import_module(f"{package}.{kind}")
        return getattr(module, base)
    except (ImportError, AttributeError) as error:
        raise ToolError(f"cannot import {package}/{kind}/{base}: {error}") from None


def full_type_name(cls: type) -> str:
    """The ROS 2 name of a generated class, e.g. 'std_msgs/msg/String'."""
    package, kind = cls.__module__.split(".")[:2]
    return f"{package}/{kind}/{cls.__name__}"
