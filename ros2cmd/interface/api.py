"""What `ros2 interface`'s sub-verbs (verb/) and ROS 1's rosmsg/rossrv (ros1/rosmsg.py) share
(ROS 2's ros2interface): the types the ament index lists and their definition files, and the
lines `show` prints after each field, with comments as rosidl's parser decides them (the
package's docstring, ros2cmd/interface/__init__.py, says what each sub-verb prints)."""

from __future__ import annotations

import argparse
import re
import sys
import textwrap

from ros2cmd.errors import ToolError
from ros2cmd.typenames import (
    KIND_NAMES,
    KINDS,
    interface_index,
    interface_package,
    list_hint,
    parse_type_name,
)
from ros_tutorials_common.ament import definition_path
from ros_tutorials_common.bounded import InputError, read_line

PRIMITIVE_TYPES = {
    "bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16",
    "int32", "uint32", "int64", "uint64", "string", "wstring", "duration", "time",
}  # fmt: skip
SEPARATOR = "---"  # between request and response (and feedback, in an action)
KIND_TITLES = {"msg": "Messages", "srv": "Services", "action": "Actions"}
# rosidl's parser takes one "[unit]" out of a comment ("# distance [m]").
_UNIT = re.compile(r"(\s*\[([^,\]]+)\])")


def _field_type(line: str) -> str | None:
    """The type of the field a definition line declares, without array or bound suffixes."""
    code = line.split("#", 1)[0].strip()
    if not code or code == SEPARATOR:
        return None
    return re.split(r"[\[<]", code.split()[0], maxsplit=1)[0]


def definition_text(
    package: str, kind: str, base: str, indent: str = "\t", comments: bool = True
) -> str:
    """A type's definition, each field of a message type followed by that type's fields:
    what `rosmsg show` printed (indent two spaces, no comments)."""
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


def _comment(text: str) -> str | None:
    """What rosidl keeps of a comment ('#' and following text): None if nothing."""
    text = text.lstrip("#")
    units = _UNIT.findall(text)
    if len(units) == 1:
        text = text.replace(units[0][0], "")
    return textwrap.dedent(text) if text else None


class DefinitionLine:
    """One line of an interface file, as ros2interface's `show` sees it. (A plain class: the
    dataclasses module would cost every `ros2` command about 8 ms to load, see graph.py.)"""

    def __init__(self, text: str, code: str = "") -> None:
        self.text = text  # as in the file, trailing white space removed
        self.is_comment = False  # a whole-line comment: left out without comments
        self.code = code  # the text without its trailing comment (when it has one)
        self.nested_type: str | None = None  # 'pkg/msg/Name' of a field of a message type

    @classmethod
    def parse(cls, text: str, package: str) -> DefinitionLine:
        text = text.rstrip()
        line = cls(text, code=text)
        parsed = text.replace("\t", " ")  # rosidl reads tabs as spaces
        if not parsed or parsed == SEPARATOR:
            return line
        if parsed.startswith("#"):
            line.is_comment = _comment(parsed) is not None
            return line
        code, hash_sign, comment = parsed.partition("#")
        if hash_sign and not code.strip():
            return line  # an indented comment: rosidl ignores it, and so it stays
        if hash_sign and (trailing := _comment(comment)) is not None:
            # ros2interface cuts the line where the comment's text is found.
            line.code = text[: text.find(trailing.split("\n")[0]) - 1].strip()
        type_string, _, rest = code.strip().partition(" ")
        if "=" not in rest:  # a field, not a constant
            type_string = type_string.split("[", 1)[0]
            if "<=" not in type_string and type_string not in PRIMITIVE_TYPES:
                nested_package, _, name = type_string.rpartition("/")
                line.nested_type = f"{nested_package or package}/msg/{name}"
        return line


def show_lines(
    package: str, kind: str, base: str, comments: bool = True, nested_comments: bool = False
) -> list[str]:
    """`ros2 interface show`'s lines for one type (nested types indented by tabs)."""
    lines = []
    for raw in definition_path(package, kind, base).read_text().splitlines():
        line = DefinitionLine.parse(raw, package)
        if comments:
            lines.append(line.text)
        elif line.text and not line.is_comment:
            lines.append(line.code)
        if line.nested_type:
            nested_package, _, nested = line.nested_type.split("/")
            nested_lines = show_lines(
                nested_package, "msg", nested, nested_comments, nested_comments
            )
            lines.extend("\t" + nested_line if nested_line else "" for nested_line in nested_lines)
    return lines


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


def show(
    type_name: str,
    ros1_style: bool = False,
    kinds: tuple[str, ...] = KINDS,
    comments: bool = True,
    all_comments: bool = False,
) -> None:
    type_name = type_name_argument(type_name)
    package, kind, base = parse_type_name(type_name, kinds)
    if ros1_style:
        if "/" not in type_name:  # rosmsg says which package it found the name in
            print(f"[{package}/{base}]:")
        print(definition_text(package, kind, base, indent="  ", comments=False))
    else:
        lines = show_lines(package, kind, base, comments or all_comments, all_comments)
        if lines:  # an empty file (std_msgs/msg/Empty) prints nothing
            print(*lines, sep="\n")


def list_types(
    kinds: tuple[str, ...] = KINDS, package: str | None = None, sort: bool = False
) -> list[str]:
    index = interface_index()
    if package is not None:
        package = interface_package(package, index)
        if package not in index:
            raise ToolError(f"unknown interface package '{package}'; {list_hint(kinds)}")
    packages = [package] if package else sorted(index)
    found = [
        f"{pkg}/{name}" for pkg in packages for name in index[pkg] if name.split("/")[0] in kinds
    ]
    return sorted(found) if sort else found


def packages(kinds: tuple[str, ...] = KINDS) -> list[str]:
    return sorted({name.split("/")[0] for name in list_types(kinds)})


def add_kind_flags(parser: argparse.ArgumentParser, verb: str) -> None:
    for short, long, kind in (
        ("-m", "--only-msgs", "msg"),
        ("-s", "--only-srvs", "srv"),
        ("-a", "--only-actions", "action"),
    ):
        parser.add_argument(
            short,
            long,
            dest="kinds",
            action="append_const",
            const=kind,
            help=f"{verb} only the {KIND_NAMES[kind]} types",
        )


def chosen_kinds(args: argparse.Namespace) -> tuple[str, ...]:
    """The kinds -m/-s/-a chose, in ros2interface's order; all three if none."""
    return tuple(kind for kind in KINDS if kind in (args.kinds or KINDS))
