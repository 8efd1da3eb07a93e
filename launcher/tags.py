"""The tags of the markup formats (roslaunch's XML; ROS 2's XML and YAML): one table, filled
by ``@tag`` on each tag's handler in the format's front-end module (launcher/ros1.py,
launcher/ros2_markup.py), and what is read from it: where each tag and attribute may stand,
and which format a file is in.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from launch_foundation.errors import LaunchError
from launch_foundation.parse import YAML_SUFFIXES, Element

if TYPE_CHECKING:
    from launcher.scope import Scope

CONDITIONS = {"if", "unless"}
PROCESS_ATTRS = {"args", "output", "respawn", "respawn_delay", "respawn_max_retries",
                 "sigterm_timeout", "sigkill_timeout", "launch_prefix", "on_exit", "shell",
                 "emulate_tty"}  # fmt: skip
SYNTAX = {"ros1": "ROS 1 (roslaunch)", "ros2": "ROS 2"}
# Attributes kept with _ inside (parse.py) that both formats document with - (both accepted).
SPELLING = {"launch_prefix": "launch-prefix"}


@dataclass(frozen=True)
class Tag:
    """One tag of one format: its handler, its attributes and the parents it may appear in."""

    handler: Callable[[Any, Element, Scope], None]  # a method of the format's front-end
    attrs: frozenset[str]
    under: frozenset[str]  # "launch" (the file's top level and <group>), "node", "executable"
    marks: frozenset[str]  # attributes that show a file is in this format (type= on <node>)


# Every tag of each format, filled by @tag on the front-ends' handlers. The allowed tags and
# attributes and the format detection are all read from here: adding a tag is one handler.
TAGS: dict[str, dict[str, Tag]] = {"ros1": {}, "ros2": {}}


def tag(
    fmt: str,
    name: str,
    attrs: Iterable[str],
    under: Iterable[str] = ("launch",),
    marks: Iterable[str] = (),
) -> Callable:
    """Register a front-end's method as the handler of <name> in ``fmt`` (ros2/launch's
    @expose_action). A tag only one format has also tells the format of the file it is in."""

    def register(handler: Callable) -> Callable:
        TAGS[fmt][name] = Tag(handler, frozenset(attrs), frozenset(under), frozenset(marks))
        return handler

    return register


def allowed_tags(fmt: str, parent: str) -> dict[str, frozenset[str]]:
    """The tags ``fmt`` allows under ``parent`` ("launch", "node", "executable"), and their
    attributes."""
    return {name: known.attrs for name, known in TAGS[fmt].items() if parent in known.under}


_SUBSTITUTION_SIGNS = {
    "ros1": re.compile(r"\$\(\s*(arg|find|optenv)\s"),
    "ros2": re.compile(r"\$\(\s*(var|find-pkg-share|find-pkg-prefix|find-exec|not|and|or|equals"
                       r"|command)\s"),
}  # fmt: skip
# roslaunch tags this launcher does not run: a sign of a ROS 1 file, and why each is refused.
ROS1_UNSUPPORTED = {
    "machine": "remote machines are roslaunch's (ROS 2 nodes find each other by discovery: "
    "start the node on that machine)",
}
# Where an element stands, as TAGS' ``under`` names it.
_PLACE = {"launch": "launch", "group": "launch", "timer": "launch", "node": "node",
          "executable": "executable", "node_container": "node_container",
          "load_composable_node": "node_container",
          "composable_node": "composable_node"}  # fmt: skip


def _sign(fmt: str, element: Element, parent: str) -> str | None:
    """What in ``element`` (a child of a ``parent`` place) only ``fmt`` has: its tag, a tag in
    that place, an attribute (``<arg value>``, ``<node type>``) or a substitution; else None."""
    if fmt == "ros1" and element.tag in ROS1_UNSUPPORTED:
        return f"<{element.tag}>"
    other = TAGS["ros2" if fmt == "ros1" else "ros1"]
    known, theirs = TAGS[fmt].get(element.tag), other.get(element.tag)
    if known is not None and parent in known.under:
        if theirs is None:
            return f"<{element.tag}>"
        if parent not in theirs.under:
            return f"<{element.tag}> in <{parent}>"
        marks = sorted(known.marks & element.attrs.keys())
        if marks:
            return f"<{element.tag} {element.spelled.get(marks[0], marks[0])}=...>"
    for value in element.attrs.values():
        if found := _SUBSTITUTION_SIGNS[fmt].search(value):
            return f"$({found[1]} ...)"
    return None


def detect(root: Element) -> tuple[str, str]:
    """The file's format, "ros1" or "ros2", from every sign of one in it (else from its name),
    and why, for the errors a wrong guess would cause."""
    first: dict[str, tuple[Element, str] | None] = {"ros1": None, "ros2": None}
    stack = [(child, "launch") for child in reversed(root.children)]
    while stack:  # in the file's order, so the first sign is the earliest line
        element, parent = stack.pop()
        place = _PLACE.get(element.tag, element.tag)
        stack.extend((child, place) for child in reversed(element.children))
        for fmt, found in first.items():
            if found is None and (sign := _sign(fmt, element, parent)):
                first[fmt] = (element, sign)
    if root.file.suffix in YAML_SUFFIXES:  # launch_yaml is a ROS 2 front-end only
        return "ros2", "a YAML launch file"
    ros1, ros2 = first["ros1"], first["ros2"]
    if ros1 and ros2:
        raise LaunchError(
            f"{root.file}: mixes ROS 1 syntax (line {ros1[0].line}: {ros1[1]}) "
            f"and ROS 2 syntax (line {ros2[0].line}: {ros2[1]})"
        )
    for fmt, found in first.items():
        if found:
            return fmt, f"line {found[0].line}: {found[1]}"
    if root.file.name.endswith(".launch"):
        return "ros1", "nothing in it is only ROS 1 or only ROS 2, and its name ends in .launch"
    return "ros2", "nothing in it is only ROS 1 or only ROS 2, and its name is not *.launch"


def detect_format(root: Element) -> str:
    """ "ros1" or "ros2", from the syntax used in the file (else from its name)."""
    return detect(root)[0]


def check_attributes(element: Element, allowed: set[str] | frozenset[str], note: str = "") -> None:
    """Only ``allowed`` attributes (and if/unless); ``note`` ends the error (the format)."""
    for name in element.attrs:
        if name not in allowed | CONDITIONS:
            known = ", ".join(sorted(SPELLING.get(a, a) for a in allowed | CONDITIONS))
            written = element.spelled.get(name, name)  # as the file wrote it
            raise element.error(
                f"unknown attribute {written!r} on <{element.tag}>; allowed: {known}{note}"
            )
    if "if" in element.attrs and "unless" in element.attrs:
        raise element.error("use either 'if' or 'unless', not both")


def check_tag(element: Element, allowed: dict, scope: Scope, parent: str) -> None:
    """``element`` is one of the ``allowed`` tags (tag -> attributes) under ``parent``."""
    fmt = scope.fmt
    if fmt == "ros1" and element.tag in ROS1_UNSUPPORTED:
        raise element.error(f"<{element.tag}> is not supported: {ROS1_UNSUPPORTED[element.tag]}")
    if element.tag not in allowed:
        known = ", ".join(f"<{name}>" for name in sorted(allowed))
        raise element.error(
            f"unknown tag <{element.tag}> in <{parent}> ({SYNTAX[fmt]} format); allowed: {known}"
            f"{scope.note}"
        )
    check_attributes(element, allowed[element.tag], scope.note)


def file_args(root: Element) -> list[Element]:
    """The <arg> declarations of a file, wherever they are (but not inside <include>)."""
    found, stack = [], list(reversed(root.children))
    while stack:
        element = stack.pop()
        if element.tag == "arg":
            found.append(element)
        elif element.tag != "include":
            stack.extend(reversed(element.children))
    return found
