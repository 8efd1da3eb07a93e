"""Parse a launch file into a tree of elements that remember their file and line.

Uses the standard library's expat parser directly (it reports line and column) and refuses any
DOCTYPE: without a DTD there are no entity declarations, so no external entities are fetched
and no "billion laughs" entity bomb can expand. Launch files never need a DTD.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

from launcher import LaunchError
from ros_tutorials_common.bounded import InputError, read_bytes


@dataclass
class Element:
    """One XML element: its tag, attributes, children and where it was written."""

    tag: str
    attrs: dict[str, str]
    file: Path
    line: int
    children: list[Element] = field(default_factory=list)
    text: str = ""
    spelled: dict[str, str] = field(default_factory=dict)  # attribute -> as the file wrote it

    @property
    def where(self) -> str:
        return f"{self.file}:{self.line}"

    def error(self, message: str) -> LaunchError:
        return LaunchError(f"{self.where}: {message}")


# The other two formats of ros2 launch, by file suffix (launch_ros reads .py and .yaml too).
NOT_YET = {".py": "Python", ".yaml": "YAML", ".yml": "YAML"}


def parse_file(path: Path) -> Element:
    """Parse one launch file; malformed XML raises LaunchError with file:line:column."""
    if path.suffix in NOT_YET:
        raise LaunchError(
            f"{path}: {NOT_YET[path.suffix]} launch files are not supported yet; "
            "this launcher runs XML launch files (ROS 1 .launch and ROS 2 .launch.xml)"
        )
    try:
        data = read_bytes(path)  # at most 1 MiB
    except InputError as error:
        raise LaunchError(f"launch file: {error}") from None
    return parse_bytes(data, path)


def parse_bytes(data: bytes, path: Path) -> Element:
    parser = expat.ParserCreate()
    stack: list[Element] = []
    roots: list[Element] = []

    def refuse(*_args: object) -> None:
        raise LaunchError(
            f"{path}:{parser.CurrentLineNumber}:{parser.CurrentColumnNumber + 1}: "
            "DOCTYPE and entity declarations are not allowed in launch files"
        )

    def start(tag: str, attrs: dict[str, str]) -> None:
        # Both spellings are accepted (launch-prefix, launch_prefix); keep one internally.
        spelled = {name.replace("-", "_"): name for name in attrs}
        attrs = {name.replace("-", "_"): value for name, value in attrs.items()}
        element = Element(tag.replace("-", "_"), attrs, path, parser.CurrentLineNumber)
        element.spelled = spelled
        (stack[-1].children if stack else roots).append(element)
        stack.append(element)

    def end(_tag: str) -> None:
        stack.pop()

    def text(data: str) -> None:
        if stack:
            stack[-1].text += data

    parser.StartDoctypeDeclHandler = refuse
    parser.EntityDeclHandler = refuse
    parser.ExternalEntityRefHandler = refuse
    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = text
    try:
        parser.Parse(data, True)
    except expat.ExpatError as error:
        message = expat.ErrorString(error.code)
        raise LaunchError(
            f"{path}:{error.lineno}:{error.offset + 1}: malformed XML: {message}"
        ) from None
    root = roots[0]
    if root.tag != "launch":
        raise root.error(f"the root element must be <launch>, not <{root.tag}>")
    return root
