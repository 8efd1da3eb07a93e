"""Message definitions for MCAP schemas, the way rosbag2 writes them ("ros2msg").

rosbag2's LocalMessageDefinitionSource stores, for each topic type, the type's own .msg file
followed by every type it uses, each once, after a line of 80 '=' and a ``MSG: pkg/Name``
line; dependencies are found by the first word of each line and visited depth first, in
sorted order. Readers (Foxglove, the ``mcap`` and ``rosbags`` packages, ``ros2 bag``) parse
exactly that text, so it is reproduced here from the .msg files the ament index lists.
"""

from __future__ import annotations

import re

from ros_tutorials_common.ament import definition_path
from ros_tutorials_common.errors import ToolError

SCHEMA_ENCODING = "ros2msg"
DELIMITER = "=" * 80 + "\n"
# rosbag2's MSG_FIELD_TYPE_REGEX: the first word of a line that is followed by whitespace.
_FIELD_TYPE = re.compile(r"(?:^|\n)\s*([a-zA-Z0-9_/]+)(?:\[[^\]]*\])?\s+")
_TYPE_NAME = re.compile(r"^([a-zA-Z0-9_]+)/(?:msg/)?([a-zA-Z0-9_]+)$")
PRIMITIVE_TYPES = frozenset(
    ["bool", "byte", "char", "float32", "float64", "string"]
    + [f"{sign}int{bits}" for sign in ("", "u") for bits in (8, 16, 32, 64)]
)
MAX_DEPTH = 50  # rosbag2's recursion limit


def _read_msg(type_name: str) -> tuple[str, str]:
    """'std_msgs/msg/Header' or 'std_msgs/Header' -> (package, text of Header.msg)."""
    match = _TYPE_NAME.match(type_name)
    if not match:
        raise ToolError(f"cannot find a definition for '{type_name}': not a pkg/msg/Name type")
    package, base = match.groups()
    path = definition_path(package, "msg", base)
    return package, path.read_text()


def dependencies(text: str, package: str) -> list[str]:
    """The message types a .msg text uses, as 'pkg/Name', sorted (rosbag2 keeps a std::set)."""
    found = set()
    for match in _FIELD_TYPE.finditer(text):
        name = match.group(1)
        if name in PRIMITIVE_TYPES:
            continue
        found.add(name if "/" in name else f"{package}/{name}")
    return sorted(found)


def message_definition(type_name: str) -> str:
    """The full ros2msg text of a message type with all its dependencies, as rosbag2 writes it.

    ToolError if the type's .msg (or a dependency's) is not installed.
    """
    seen: set[str] = set()

    def append(name: str, depth: int) -> str:
        if depth <= 0:
            raise ToolError(f"definition of {type_name} nests too deep")
        package, text = _read_msg(name)
        result = text
        for dependency in dependencies(text, package):
            if dependency not in seen:
                seen.add(dependency)
                result += "\n" + DELIMITER + f"MSG: {dependency}\n" + append(dependency, depth - 1)
        return result

    return append(type_name, MAX_DEPTH)


def service_definition(service_type: str) -> tuple[str, str]:
    """(text, encoding) of a service event topic's schema, as rosbag2 (Jazzy) writes it.

    rosbag2 looks up the service (`pkg/srv/Name`, the event type without `_Event`): a line
    of '=' and `SRV: pkg/srv/Name`, the .srv file, then each message type it uses as above.
    The encoding is "ros2msg" only when some message type was appended; a .srv of primitive
    fields alone (AddTwoInts) gets "unknown", which is what rosbag2 stores for it.
    """
    package, _, base = service_type.split("/")
    text = DELIMITER + f"SRV: {service_type}\n" + definition_path(package, "srv", base).read_text()
    seen = {service_type}
    encoding = "unknown"

    def append(name: str, depth: int) -> str:
        if depth <= 0:
            raise ToolError(f"definition of {service_type} nests too deep")
        dependency_package, body = _read_msg(name)
        result = body
        for dependency in dependencies(body, dependency_package):
            if dependency not in seen:
                seen.add(dependency)
                result += "\n" + DELIMITER + f"MSG: {dependency}\n" + append(dependency, depth - 1)
        return result

    for dependency in dependencies(text.split("\n", 2)[2], package):
        if dependency not in seen:
            seen.add(dependency)
            text += "\n" + DELIMITER + f"MSG: {dependency}\n" + append(dependency, MAX_DEPTH)
            encoding = SCHEMA_ENCODING
    return text, encoding


def schema(type_name: str) -> tuple[str, str]:
    """(definition, encoding) stored for the type, as rosbag2 stores it."""
    if type_name.endswith("_Event") and "/srv/" in type_name:
        return service_definition(type_name[: -len("_Event")])
    return message_definition(type_name), SCHEMA_ENCODING
