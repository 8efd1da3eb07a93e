"""`ros2 interface ...`: the message, service and action types installed (like `ros2 interface`).

These commands need no running graph: they read the ament resource index and the
definition files each interface package installs under share/<package>/.
"""

from __future__ import annotations

import argparse
import re
import sys

from ros2cmd.errors import ToolError
from ros2cmd.typenames import (
    KIND_NAMES,
    KINDS,
    definition_path,
    interface_index,
    interface_package,
    list_hint,
    parse_type_name,
)
from ros_tutorials_common.bounded import InputError, read_line

PRIMITIVE_TYPES = {
    "bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16",
    "int32", "uint32", "int64", "uint64", "string", "wstring",
}  # fmt: skip


def _field_type(line: str) -> str | None:
    """The type of the field a definition line declares, without array or bound suffixes."""
    code = line.split("#", 1)[0].strip()
    if not code or code == "---":
        return None
    return re.split(r"[\[<]", code.split()[0], maxsplit=1)[0]


def definition_text(
    package: str, kind: str, base: str, indent: str = "\t", comments: bool = True
) -> str:
    """A type's definition, each field of a message type followed by that type's fields.

    `ros2 interface show` expands nested types (tab-indented) so the learner sees every
    field they can set; `rosmsg show` did the same with two spaces and no comments.
    """
    lines = []
    for line in definition_path(package, kind, base).read_text().splitlines():
        if not comments:
            line = line.split("#", 1)[0].rstrip()
            if not line:
                continue
        lines.append(line)
        field_type = _field_type(line)
        if field_type and field_type not in PRIMITIVE_TYPES:
            nested_package, _, nested = field_type.rpartition("/")
            nested_text = definition_text(
                nested_package or package, "msg", nested, indent, comments=False
            )
            lines.extend(indent + nested_line for nested_line in nested_text.splitlines())
    return "\n".join(lines)


def type_name_argument(type_name: str) -> str:
    """'-' means: read the name from standard input (`rosservice type /spawn | rossrv show`)."""
    if type_name != "-":
        return type_name
    try:  # from a pipe: one line, bounded (`rossrv show < /dev/zero` must not fill memory)
        type_name = read_line(sys.stdin, "standard input").strip()
    except InputError as error:
        raise ToolError(str(error)) from None
    if not type_name:
        raise ToolError("no type name given, and none on standard input")
    return type_name


def show(type_name: str, ros1_style: bool = False, kinds: tuple[str, ...] = KINDS) -> None:
    type_name = type_name_argument(type_name)
    package, kind, base = parse_type_name(type_name, kinds)
    if ros1_style:
        if "/" not in type_name:  # rosmsg says which package it found the name in
            print(f"[{package}/{base}]:")
        print(definition_text(package, kind, base, indent="  ", comments=False))
    else:
        print(definition_text(package, kind, base))


def list_types(kinds: tuple[str, ...] = KINDS, package: str | None = None) -> list[str]:
    index = interface_index()
    if package is not None:
        package = interface_package(package, index)
        if package not in index:
            raise ToolError(f"unknown interface package '{package}'; {list_hint(kinds)}")
    packages = [package] if package else sorted(index)
    return [
        f"{pkg}/{name}" for pkg in packages for name in index[pkg] if name.split("/")[0] in kinds
    ]


def list_command(kinds: tuple[str, ...]) -> None:
    titles = {"msg": "Messages", "srv": "Services", "action": "Actions"}
    for kind in kinds:
        print(f"{titles[kind]}:")
        for name in list_types((kind,)):
            print(f"    {name}")


def packages(kinds: tuple[str, ...] = KINDS) -> list[str]:
    return sorted({name.split("/")[0] for name in list_types(kinds)})


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("interface", help="interface types: list, show, package, packages")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    p = sub.add_parser("list", help="list the installed message, service and action types")
    for flag, kind in (("-m", "msg"), ("-s", "srv"), ("-a", "action")):
        p.add_argument(
            flag, dest="kinds", action="append_const", const=kind, help=f"{KIND_NAMES[kind]}s"
        )
    p.set_defaults(offline=True, run=lambda _, a: list_command(tuple(a.kinds or KINDS)))

    p = sub.add_parser("show", help="print a type's definition ('-' reads the name from stdin)")
    p.add_argument("type", help="e.g. ros_tutorials_interfaces/msg/MsgTutorial")
    p.set_defaults(offline=True, run=lambda _, a: show(a.type))

    p = sub.add_parser("package", help="list the types of one package")
    p.add_argument("package")
    p.set_defaults(offline=True, run=lambda _, a: print(*list_types(package=a.package), sep="\n"))

    p = sub.add_parser("packages", help="list the packages that define interface types")
    p.set_defaults(offline=True, run=lambda _, a: print(*packages(), sep="\n"))
