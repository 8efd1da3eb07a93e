"""Parse a launch file into a tree of elements that remember their file and line.

XML: the standard library's expat parser directly (it reports line and column), refusing any
DOCTYPE: without a DTD there are no entity declarations, so no external entities are fetched
and no "billion laughs" entity bomb can expand. Launch files never need a DTD.

YAML (launch_yaml): the same elements, so one resolver reads both. ``launch:`` is a list of
entities ``{tag: {attribute: value, ...}}``; a list under an attribute is a list of child
elements of that tag (``remap:``, ``param:``, ``arg:``, ``env:``, ``choice:``), except
``children:``, a list of entities (``group``, ``timer``). A list of plain values is an
attribute written as a YAML flow list (``value: [1, 2]``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING
from xml.parsers import expat

from launch_foundation.errors import LaunchError
from ros_tutorials_common.bounded import (
    MAX_YAML_NODES,
    InputError,
    _expanded_size,
    bounded_loader,
    read_bytes,
)

if TYPE_CHECKING:
    import yaml


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


YAML_SUFFIXES = (".yaml", ".yml")


def parse_file(path: Path) -> Element:
    """Parse one XML or YAML launch file; malformed input raises LaunchError with file:line."""
    try:
        data = read_bytes(path)  # at most 1 MiB
    except InputError as error:
        raise LaunchError(f"launch file: {error}") from None
    if path.suffix in YAML_SUFFIXES:
        return parse_yaml(data, path)
    return parse_bytes(data, path)


def parse_yaml(data: bytes, path: Path) -> Element:
    """A launch_yaml file as the elements the XML front-end gives (see the module docstring)."""
    import yaml  # here: an XML launch file reads no YAML

    try:
        loader = bounded_loader(data.decode("utf-8"))
        try:
            root = loader.get_single_node()
        finally:
            loader.dispose()
    except UnicodeDecodeError:
        raise LaunchError(f"{path}: not UTF-8 text") from None
    except InputError as error:
        raise LaunchError(f"{path}: {error}") from None
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark
        where = f"{path}:{mark.line + 1}:{mark.column + 1}" if mark else str(path)
        raise LaunchError(f"{where}: malformed YAML: {error.problem}") from None
    except yaml.YAMLError as error:
        raise LaunchError(f"{path}: malformed YAML: {error}") from None
    if root is not None and _expanded_size(root) > MAX_YAML_NODES:
        raise LaunchError(f"{path}: more than {MAX_YAML_NODES} values once aliases expand")
    if not isinstance(root, yaml.MappingNode) or [k.value for k, _ in root.value] != ["launch"]:
        line = root.start_mark.line + 1 if root is not None else 1
        raise LaunchError(f"{path}:{line}: a YAML launch file is one mapping, 'launch:' a list")
    key, body = root.value[0]
    launch = Element("launch", {}, path, key.start_mark.line + 1)
    if isinstance(body, yaml.ScalarNode) and body.value in ("", "~", "null"):
        return launch  # an empty launch file
    launch.children = _yaml_entities(body, path)
    return launch


def _yaml_error(node: yaml.Node, path: Path, message: str) -> LaunchError:
    return LaunchError(f"{path}:{node.start_mark.line + 1}: {message}")


def _yaml_entities(node: yaml.Node, path: Path) -> list[Element]:
    """A list of entities: each a mapping of one tag to its attributes and children."""
    import yaml

    if not isinstance(node, yaml.SequenceNode):
        raise _yaml_error(node, path, "expected a list of entities (- node: ..., - arg: ...)")
    entities = []
    for item in node.value:
        if not isinstance(item, yaml.MappingNode) or len(item.value) != 1:
            raise _yaml_error(item, path, "each entity is one tag: '- node:', '- arg:', ...")
        key, body = item.value[0]
        entities.append(_yaml_element(key.value, body, path, key.start_mark.line + 1))
    return entities


def _yaml_element(tag: str, body: yaml.Node, path: Path, line: int) -> Element:
    import yaml

    element = Element(tag.replace("-", "_"), {}, path, line)
    if isinstance(body, yaml.ScalarNode):
        if body.value not in ("", "~", "null"):
            raise _yaml_error(body, path, f"'{tag}:' takes attributes (name: value), not a value")
        return element
    if not isinstance(body, yaml.MappingNode):
        raise _yaml_error(body, path, f"'{tag}:' takes attributes (name: value), not a list")
    for key_node, value in body.value:
        key = str(key_node.value)
        name = key.replace("-", "_")
        if name in element.attrs or any(child.tag == name for child in element.children):
            raise _yaml_error(key_node, path, f"'{key}' is written twice in '{tag}'")
        if isinstance(value, yaml.ScalarNode):
            element.attrs[name] = value.value
            element.spelled[name] = key
        elif isinstance(value, yaml.SequenceNode) and name == "children":
            element.children += _yaml_entities(value, path)
        elif isinstance(value, yaml.SequenceNode) and all(
            isinstance(item, yaml.MappingNode) for item in value.value
        ):
            for item in value.value:
                element.children.append(_yaml_element(key, item, path, item.start_mark.line + 1))
        elif isinstance(value, yaml.SequenceNode) and all(
            isinstance(item, yaml.ScalarNode) for item in value.value
        ):
            plain = yaml.safe_load(yaml.serialize(value))
            element.attrs[name] = yaml.safe_dump(plain, default_flow_style=True).strip()
            element.spelled[name] = key
        else:
            raise _yaml_error(value, path, f"'{key}' in '{tag}': unsupported value")
    return element


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
