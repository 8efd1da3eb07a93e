"""`ros2 interface ...`: the message, service and action types installed (ROS 2's ros2interface).

    ros2 interface list [-m|-s|-a]          Messages: / Services: / Actions:, types indented
    ros2 interface show geometry_msgs/msg/Twist [--all-comments | --no-comments]
    ros2 interface package turtlesim        ros2 interface packages [-m|-s|-a]
    ros2 interface proto geometry_msgs/msg/Twist     the YAML a `topic pub` takes, quoted

These commands need no running graph: they read the ament resource index and the
definition files each interface package installs under share/<package>/.
`show` prints the file as it is, and after each field of a message type that type's
definition, indented by a tab, without its comments (unless --all-comments): what a
learner can set. Which lines count as comments is decided as rosidl's parser does it,
so the output is ros2interface's line for line (quirks included: a lone `#` or an indented
comment is not a comment to it, and stays).
"""

from __future__ import annotations

import argparse
import re
import sys
import textwrap

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.sub_verbs import VERB_HELP
from ros2cmd.typenames import (
    KIND_NAMES,
    KINDS,
    interface_index,
    interface_package,
    list_hint,
    load_type,
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


def proto(type_name: str, quotes: bool = True) -> None:
    """`ros2 interface proto`: a default message (a goal, a request) as YAML."""
    import yaml

    from ros2cmd.messages import message_to_data  # loads rclpy's generated classes: only here

    cls = load_type(type_name)
    kind = parse_type_name(type_name)[1]
    instance = cls.Goal() if kind == "action" else cls.Request() if kind == "srv" else cls()
    # rosidl_runtime_py's message_to_yaml: block style, lines never wrapped, "{}\n" if empty.
    text = yaml.safe_dump(
        message_to_data(instance),
        default_flow_style=False,
        sort_keys=False,
        allow_unicode=True,
        width=sys.maxsize,
    )
    print(f'"{text}"' if quotes else text)


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


def list_command(kinds: tuple[str, ...]) -> None:
    for kind in kinds:
        print(f"{KIND_TITLES[kind]}:")
        for name in list_types((kind,), sort=True):
            print(f"    {name}")


def package_command(package: str, kinds: tuple[str, ...] | None) -> None:
    """`ros2 interface package PKG`: its types, sorted (ros2interface's order is a set's),
    or kind by kind as -m/-s/-a are given."""
    names = list_types(KINDS, package, sort=True) if kinds is None else []
    for kind in kinds or ():
        names += list_types((kind,), package, sort=True)
    if names:
        print(*names, sep="\n")


def packages(kinds: tuple[str, ...] = KINDS) -> list[str]:
    return sorted({name.split("/")[0] for name in list_types(kinds)})


def _kind_flags(parser: argparse.ArgumentParser, verb: str) -> None:
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


def _kinds(args: argparse.Namespace) -> tuple[str, ...]:
    """The kinds -m/-s/-a chose, in ros2interface's order; all three if none."""
    return tuple(kind for kind in KINDS if kind in (args.kinds or KINDS))


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("interface", help=VERB_HELP["interface"])
    sub = parser.add_subparsers(dest="command", metavar="Commands", required=True)

    p = sub.add_parser("list", help="List all interface types available")
    _kind_flags(p, "Print out")
    p.set_defaults(offline=True, run=lambda _, a: list_command(_kinds(a)))

    p = sub.add_parser(
        "package", help="Output a list of available interface types within one package"
    )
    _kind_flags(p, "Print out")
    p.add_argument("package", help="Name of the ROS package (e.g. 'example_interfaces')")
    completion.attach(p, package=completion.interface_packages)
    p.set_defaults(offline=True, run=lambda _, a: package_command(a.package, a.kinds and _kinds(a)))

    p = sub.add_parser("packages", help="Output a list of packages that provide interfaces")
    _kind_flags(p, "List")
    p.set_defaults(offline=True, run=lambda _, a: print(*packages(_packages_kind(a)), sep="\n"))

    p = sub.add_parser("proto", help="Output an interface prototype")
    p.add_argument(
        "type", help="Show an interface definition (e.g. 'example_interfaces/msg/String')"
    )
    completion.attach(p, type=completion.all_types)
    p.add_argument("--no-quotes", action="store_true", help="if true output has no outer quotes.")
    p.set_defaults(offline=True, run=lambda _, a: proto(a.type, quotes=not a.no_quotes))

    p = sub.add_parser("show", help="Output the interface definition")
    comments = p.add_mutually_exclusive_group()
    comments.add_argument(
        "--all-comments",
        action="store_true",
        help="Show all comments, including for nested interface definitions",
    )
    comments.add_argument(
        "--no-comments", action="store_true", help="Show no comments or whitespace"
    )
    p.add_argument(
        "type",
        help="Show an interface definition (e.g. 'example_interfaces/msg/String'). Passing '-' "
        "reads the argument from stdin (e.g. 'ros2 topic type /chatter | ros2 interface show -').",
    )
    completion.attach(p, type=completion.all_types)
    p.set_defaults(
        offline=True,
        run=lambda _, a: show(a.type, comments=not a.no_comments, all_comments=a.all_comments),
    )


def _packages_kind(args: argparse.Namespace) -> tuple[str, ...]:
    """`packages -m -s` lists the message packages: ros2interface takes the first flag only."""
    return _kinds(args)[:1] if args.kinds else KINDS
